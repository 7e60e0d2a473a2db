// touchline_walk_engine_bench: what each walk engine costs per 10 ms world motion tick
// (the MotionAdapter with the engine, its kinematics and the feet it hands the world), and
// how fast each walks against the request: forward, sideways and turning, body velocity
// from the odometry between 3 s and 8 s of a constant request (after the ramp).
// Usage: touchline_walk_engine_bench [--ticks N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "touchline/angles.hpp"
#include "touchline/robot/motion_adapter.hpp"
#include "touchline/robot/walk_engines.hpp"

using namespace touchline;
using namespace touchline::robot;
using Clock = std::chrono::steady_clock;

namespace {

struct EngineCase {
  const char* label;
  const char* name;
  int64_t period_us;
};

MotionAdapter make(const EngineCase& c, std::ostream& warnings) {
  WalkEngineDef def;
  def.name = c.name;
  def.nao_joints.period_us = c.period_us;
  MotionDef motion;
  motion.warnings = &warnings;
  return MotionAdapter(make_walk_engine(def, WalkDef{}, KickDef{}), motion);
}

/// Median microseconds per world tick, timed in batches of 100 ticks, walking at
/// 200 mm/s and turning 0.5 rad/s.
double cost_us(const EngineCase& c, int ticks) {
  std::ostringstream warnings;
  MotionAdapter motion = make(c, warnings);
  api::Blackboard blackboard;
  blackboard.behaviour.request.body = api::ActionCommand::walk(200, 0, 0.5f);
  std::vector<double> batches;
  for (int done = 0; done < ticks; done += 100) {
    const auto start = Clock::now();
    for (int i = 0; i < 100; ++i) motion.tick(blackboard);
    batches.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count() / 100);
  }
  std::sort(batches.begin(), batches.end());
  return batches[batches.size() / 2];
}

/// Body velocity in the start frame between 3 s and 8 s: forward, left (mm/s), turn (rad/s).
std::vector<double> velocity(const EngineCase& c, const api::ActionCommand::Body& body) {
  std::ostringstream warnings;
  MotionAdapter motion = make(c, warnings);
  api::Blackboard blackboard;
  blackboard.behaviour.request.body = body;
  double heading = 0, heading_at_3 = 0;
  float last = 0;
  api::AbsCoord at_3;
  for (int tick = 1; tick <= 800; ++tick) {
    motion.tick(blackboard);
    heading += normalise_angle(blackboard.motion.odometry.theta - last);
    last = blackboard.motion.odometry.theta;
    if (tick == 300) {
      at_3 = blackboard.motion.odometry;
      heading_at_3 = heading;
    }
  }
  const auto& end = blackboard.motion.odometry;
  if (!warnings.str().empty()) std::cerr << warnings.str();
  return {(end.x - at_3.x) / 5, (end.y - at_3.y) / 5, (heading - heading_at_3) / 5};
}

/// The engine's own odometry over the same 3 s to 8 s, where it keeps one (else empty).
std::vector<double> own_velocity(const EngineCase& c, const api::ActionCommand::Body& body) {
  std::ostringstream warnings;
  MotionAdapter motion = make(c, warnings);
  if (!motion.engine().own_odometry()) return {};
  api::Blackboard blackboard;
  blackboard.behaviour.request.body = body;
  Pose2D at_3;
  for (int tick = 1; tick <= 800; ++tick) {
    motion.tick(blackboard);
    if (tick == 300) at_3 = *motion.engine().own_odometry();
  }
  const Pose2D end = *motion.engine().own_odometry();
  return {(end.x_mm - at_3.x_mm) / 5, (end.y_mm - at_3.y_mm) / 5, (end.theta_rad - at_3.theta_rad) / 5};
}

} // namespace

int main(int argc, char** argv) {
  int ticks = 20000;
  if (argc == 3 && std::strcmp(argv[1], "--ticks") == 0) ticks = std::max(100, std::atoi(argv[2]));
  std::vector<EngineCase> engines = {{"walkcycle (10 ms)", "walkcycle", 10000},
                                     {"nao-joints (10 ms)", "nao-joints", 10000},
                                     {"nao-joints (12 ms)", "nao-joints", 12000}};
  const auto names = walk_engine_names();
  if (std::find(names.begin(), names.end(), "runswift") != names.end())
    engines.push_back({"runswift (12.2 ms)", "runswift", 12200}); // a build with their code
  std::cout << std::fixed << std::setprecision(2);
  std::cout << "cost per 10 ms world tick (median of batches, walking 200 mm/s turning 0.5 rad/s):\n";
  for (const auto& e : engines) std::cout << "  " << std::setw(20) << std::left << e.label << cost_us(e, ticks) << " us\n";

  struct Request {
    const char* label;
    api::ActionCommand::Body body;
    int axis; // 0 forward, 1 left, 2 turn
    double want;
  };
  const Request requests[] = {
      {"forward 100 mm/s", api::ActionCommand::walk(100, 0, 0), 0, 100},
      {"forward 200 mm/s", api::ActionCommand::walk(200, 0, 0), 0, 200},
      {"forward 300 mm/s", api::ActionCommand::walk(300, 0, 0), 0, 300},
      {"left 100 mm/s", api::ActionCommand::walk(0, 100, 0), 1, 100},
      {"left 200 mm/s", api::ActionCommand::walk(0, 200, 0), 1, 200},
      {"turn 0.5 rad/s", api::ActionCommand::walk(0, 0, 0.5f), 2, 0.5},
      {"turn 1.0 rad/s", api::ActionCommand::walk(0, 0, 1.0f), 2, 1.0},
      {"turn 1.5 rad/s", api::ActionCommand::walk(0, 0, 1.5f), 2, 1.5},
  };
  std::cout << "speed against request (odometry, 3 s to 8 s):\n";
  for (const auto& r : requests) {
    std::cout << "  " << std::setw(18) << std::left << r.label;
    for (const auto& e : engines) {
      const double got = velocity(e, r.body)[static_cast<size_t>(r.axis)];
      std::cout << "  " << e.label << " " << std::setprecision(r.axis == 2 ? 3 : 1) << got << " ("
                << std::setprecision(1) << 100 * got / r.want << " %)";
      const auto own = own_velocity(e, r.body);
      if (!own.empty())
        std::cout << " [its own odometry " << std::setprecision(r.axis == 2 ? 3 : 1) << own[static_cast<size_t>(r.axis)]
                  << "]";
    }
    std::cout << "\n" << std::setprecision(2);
  }
  return 0;
}
