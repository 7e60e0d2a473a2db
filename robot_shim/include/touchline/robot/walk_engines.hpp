#pragma once
// The walk engines a robot can run, by name: robot_shim --walk-engine NAME, RobotDef's
// engine, tools/match --walk-engine0/1.
#include <memory>
#include <string>
#include <vector>

#include "touchline/robot/kick_generator.hpp"
#include "touchline/robot/nao_joint_walk.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot/walk_engine.hpp"

namespace touchline::robot {

struct WalkEngineDef {
  /// "walkcycle": our WalkCycle and kick planning the feet (10 ms); "nao-joints": the same
  /// plan through our inverse kinematics as a Nao's joint angles (walk_engines()).
  std::string name = "walkcycle";
  NaoJointWalkDef nao_joints; ///< the joint walk's own parameters
  /// "runswift" (built with -DTOUCHLINE_RUNSWIFT_DIR): one of their option files whose walk
  /// keys override their defaults; "" for their defaults.
  std::string runswift_config;
};

/// Every name make_walk_engine knows, the default first ("runswift" only in a build with
/// their code).
std::vector<std::string> walk_engine_names();

/// The engine `engine.name` names, planning with `walk` and `kick`. Throws ConfigError
/// "unknown walk engine 'NAME' (walkcycle, nao-joints)".
std::unique_ptr<WalkEngine> make_walk_engine(const WalkEngineDef& engine, const WalkDef& walk, const KickDef& kick);

} // namespace touchline::robot
