#pragma once
// The walk-engine seam: what the MotionAdapter drives, at the engine's own control period
// in simulated time (10 ms for the WalkCycle, 12.2 ms for rUNSWift's Walk2014Generator on
// a V6), whatever the camera frame rate. Each engine tick reads the behaviour's body
// command and the sensors fed back (nao/sensors.hpp) and gives either both feet's poses
// on the ground (a walk that plans feet, like ours) or the 25 joint angles of a Nao V6 (a
// team's own walk), which the MotionAdapter turns into feet (nao/joint_feet.hpp). The
// MotionAdapter checks every output (finite, joints within range) before it is used.
#include <cstdint>
#include <optional>
#include <string>

#include "touchline/frame.hpp"
#include "touchline/robot/nao/joints.hpp"
#include "touchline/robot/nao/sensors.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot_api/action_command.hpp"

namespace touchline::robot {

class GaitFeet;

enum class EngineOutputKind { kFeet, kJoints };

/// One engine tick's output; the fields of its kind are used.
struct WalkEngineOutput {
  FeetPose feet;              ///< kFeet: both feet, in the engine's odometry frame
  Pose2D odometry;            ///< kFeet: the body pose the engine dead-reckons
  nao::JointAngles joints{};  ///< kJoints: every joint, rad (head joints are ignored: the
                              ///< MotionAdapter points the head)
};

/// What the engine is doing, for the MotionBlackboard.
struct WalkEngineStatus {
  bool standing = true;          ///< not stepping
  int kick_phase = 0;            ///< MotionBlackboard::kickPhase (0: no kick)
  api::ActionCommand::Body active; ///< the body command being executed
};

class WalkEngine {
 public:
  virtual ~WalkEngine() = default;
  /// The name robot_shim --walk-engine knows it by.
  virtual std::string name() const = 0;
  /// The control period, simulated microseconds (> 0).
  virtual int64_t period_us() const = 0;
  virtual EngineOutputKind output_kind() const = 0;
  /// The output at time 0, before any tick: the robot standing.
  virtual void start(WalkEngineOutput& out) = 0;
  /// One control period: `request` is the behaviour's body command, `sensors` what the
  /// robot senses now.
  virtual void tick(const api::ActionCommand::Body& request, const nao::Sensors& sensors, WalkEngineOutput& out) = 0;
  virtual WalkEngineStatus status() const = 0;
  /// The referee picked the robot up and put it down standing, feet square (the world placed
  /// them so): an engine that plans feet stands there and writes them to `out`. A joint engine
  /// keeps its state (the default): its feet come from its joints, not from a plan.
  virtual void placed(WalkEngineOutput& out) { (void)out; }
  /// The engine's own odometry as it keeps it (a team's walk dead-reckons its steps: its
  /// per-tick forward, left (mm) and turn (rad) summed), to compare with what the feet did;
  /// nothing for an engine that keeps none.
  virtual std::optional<Pose2D> own_odometry() const { return std::nullopt; }
  /// The WalkCycle and kick an engine of ours plans with; nothing for a foreign engine.
  virtual const GaitFeet* gait() const { return nullptr; }
};

} // namespace touchline::robot
