#pragma once
// RunswiftWalk: rUNSWift's own walk engine (Walk2014Generator, compiled from the user's
// clone with -DTOUCHLINE_RUNSWIFT_DIR) behind Touchline's engine-neutral frames
// (touchline/robot/nao/nao_frames.hpp). Nothing of theirs is visible here: their headers
// are included by one source only (runswift_walk.cpp), because they define macros (MIN,
// MAX, ABS, DEG2RAD) and a Joints namespace.
//
// Each step() is one tick of their motion thread, in the order their MotionAdapter runs
// it: the sensors into their Kinematics, the Denavit-Hartenberg chain, their BodyModel
// (which turns the foot pressure sensors into the left/right balance that switches the
// support foot), then Walk2014Generator::makeJoints. The caller runs it every
// kControlPeriodUs of simulated time (their MOTION_DT on a V6) and feeds back, as the
// next tick's joint positions, what the joints reached.
//
// Reads: the walk command and the sensor frame. Writes: 25 joint targets and their walk's
// odometry increment, the joints clipped to their V6 ranges and speeds as their motion
// pipeline clips them. Never throws from step(): a NaN or a leg joint beyond its limits (or an
// exception of theirs) returns the last good joints with engine_fault set, and
// fault_message() names the joint.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "touchline/robot/nao/nao_frames.hpp"

namespace touchline::robot::runswift {

/// How the adapter runs their walk.
struct RunswiftWalkDef {
  /// Their .cfg files (INI) holding walk options (motion.KpGyro, kick.lean, ...), applied in
  /// order over their defaults, a later file's key winning. Empty: their defaults.
  std::vector<std::string> option_files;
  /// Their MotionAdapter negates gyro Z on a real V6 (not in their simulator mode); our frame
  /// carries the V6's sign, so the adapter does the same.
  bool negate_gyro_z = true;
  /// A leg joint up to this far beyond its V6 limit is clipped to it, as their motion
  /// pipeline (ClippedGenerator) and the joint itself do (their kick straightens a knee 0.09
  /// rad past its range); further is an engine fault, rad. Head, arm and hand joints move no
  /// foot and are only clipped (their kick swings a shoulder 0.63 rad past its range,
  /// and their walk holds the elbows at 0, 2 degrees outside theirs). NaN is always a fault.
  float leg_limit_tolerance_rad = 0.1745f;
  /// As their ClippedGenerator: no joint target moves further in a tick than the joint can
  /// (nao::kJointMaxSpeed_rad_s); their kick asks the kicking ankle for 49 rad/s, 7 times
  /// what it can do.
  bool limit_joint_speed = true;
};

class RunswiftWalk {
 public:
  /// Their walk's control period on a V6 (MOTION_DT = 12.2 ms, about 82 Hz).
  static constexpr int64_t kControlPeriodUs = 12200;

  /// Reads the option files (throws touchline::ConfigError, one line naming the file and
  /// the fault) and constructs their walk, standing.
  explicit RunswiftWalk(const RunswiftWalkDef& def = {});
  ~RunswiftWalk();
  RunswiftWalk(const RunswiftWalk&) = delete;
  RunswiftWalk& operator=(const RunswiftWalk&) = delete;

  /// One control tick. Never throws.
  nao::NaoJointFrame step(const nao::WalkCommand& command, const nao::NaoSensorFrame& sensors) noexcept;

  /// Why the last faulty tick was faulty ("LKneePitch = nan"); empty if none has been.
  const std::string& fault_message() const { return fault_message_; }
  /// Ticks that returned engine_fault so far.
  int64_t fault_ticks() const { return fault_ticks_; }

  /// For each joint, the furthest their walk has commanded it beyond its V6 limit (clipped,
  /// or a fault past leg_limit_tolerance_rad), rad; 0 for a joint always inside.
  const nao::JointArray& beyond_limit_rad() const { return beyond_limit_rad_; }

  /// Their walk's state, for tests and logs: whether the left foot is the swing foot (their
  /// BodyModel's phase; it flips when the foot pressure says the support foot changed) and
  /// their walk option ("STAND", "CROUCH", "WALK", "READY", "KICK", ...).
  bool left_foot_swinging() const;
  const char* walk_option() const;

 private:
  struct Engine; // their Walk2014Generator, Kinematics and BodyModel
  std::unique_ptr<Engine> engine_;
  RunswiftWalkDef def_;
  nao::JointArray last_good_{};
  bool have_last_good_ = false;
  nao::JointArray beyond_limit_rad_{};
  std::string fault_message_;
  int64_t fault_ticks_ = 0;
};

} // namespace touchline::robot::runswift
