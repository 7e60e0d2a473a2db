#pragma once
// The WalkCycle (and its kick) behind the walk-engine seam: a feet engine with a 10 ms
// period, exactly the walk every match played before the seam (the golden hashes hold).
#include "touchline/robot/gait_feet.hpp"
#include "touchline/robot/walk_engine.hpp"

namespace touchline::robot {

class WalkCycleEngine : public WalkEngine {
 public:
  WalkCycleEngine(const WalkDef& walk, const KickDef& kick);
  std::string name() const override { return "walkcycle"; }
  int64_t period_us() const override { return kMotionTickUs; }
  EngineOutputKind output_kind() const override { return EngineOutputKind::kFeet; }
  void start(WalkEngineOutput& out) override;
  void tick(const api::ActionCommand::Body& request, const nao::Sensors& sensors, WalkEngineOutput& out) override;
  WalkEngineStatus status() const override { return gait_.status(); }
  void placed(WalkEngineOutput& out) override;
  const GaitFeet* gait() const override { return &gait_; }

 private:
  GaitFeet gait_;
};

} // namespace touchline::robot
