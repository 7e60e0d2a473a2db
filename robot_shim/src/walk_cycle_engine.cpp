#include "touchline/robot/walk_cycle_engine.hpp"

namespace touchline::robot {

WalkCycleEngine::WalkCycleEngine(const WalkDef& walk, const KickDef& kick) : gait_(walk, kick) {}

void WalkCycleEngine::start(WalkEngineOutput& out) {
  out.feet = gait_.feet();
  out.odometry = gait_.odometry();
}

void WalkCycleEngine::placed(WalkEngineOutput& out) {
  gait_.placed();
  start(out);
}

void WalkCycleEngine::tick(const api::ActionCommand::Body& request, const nao::Sensors&, WalkEngineOutput& out) {
  gait_.tick(request, static_cast<float>(period_us()) * 1e-6f); // the same float 0.01 the walk always had
  out.feet = gait_.feet();
  out.odometry = gait_.odometry();
}

} // namespace touchline::robot
