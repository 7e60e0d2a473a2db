#pragma once
// MotionAdapter: the motion thread of the robot. The world asks for one TickMotion per
// 10 ms world motion tick (frame.hpp); the walk engine (walk_engine.hpp) runs at its own
// control period on an engine clock of integer simulated microseconds, so an engine of
// 12.2 ms runs 0 or 1 times in a world tick and never drifts. Each world tick the adapter
// points the head (at 10 ms, as before), runs every engine tick that falls before the
// world tick's end (each reads the behaviour's body command and the sensors fed back),
// and hands the world how the feet moved over the world tick: the feet at its end are
// the engine's sample there, or interpolated between the two samples around it. A joint
// engine's output becomes feet through JointFeet (forward kinematics, stance sole fixed).
// Every engine output is checked here, in one place: a NaN, or a leg joint out of its
// range, stops the engine for good (the robot stands where it is; one warning names the
// joint). Joints are fed back, and turned into feet, as the motors' stops leave them.
// Reads: blackboard.behaviour.request, blackboard.motion.fallen. Writes:
// blackboard.motion (odometry, active, standing, kickPhase, head, ticks), the effector.
#include <cstdint>
#include <iosfwd>
#include <memory>

#include "touchline/frame.hpp"
#include "touchline/robot/gait_feet.hpp"
#include "touchline/robot/head_def.hpp"
#include "touchline/robot/kick_generator.hpp"
#include "touchline/robot/nao/foot_pressure.hpp"
#include "touchline/robot/nao/joint_feet.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot/walk_engine.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::robot {

/// How the adapter turns an engine's output into feet and sensors.
struct MotionDef {
  HeadDef head;
  nao::JointFeetDef joint_feet;        ///< a joint engine's feet: stance detection, leg dimensions
  nao::FootPressureDef foot_pressure;  ///< what the FSRs read
  float joint_tolerance_rad = 0.1f;    ///< how far past its published range a leg joint command may go: the motor stops at the limit (rUNSWift's kick asks 3 degrees past the ankle's), a unit or sign error goes far beyond
  std::ostream* warnings = nullptr;    ///< where the one warning of a bad engine output goes (nullptr: std::cerr)
};

class MotionAdapter {
 public:
  /// Our WalkCycle and kick (the walkcycle engine).
  MotionAdapter(const WalkDef& walk, const HeadDef& head = {}, const KickDef& kick = {});
  /// Any engine. std::invalid_argument for none or a period that is not positive.
  MotionAdapter(std::unique_ptr<WalkEngine> engine, const MotionDef& def);

  /// The referee put the robot down (RobotSense::placed), feet square: a feet engine stands
  /// square where it is, so its next steps start from the feet the world placed.
  void placed();

  /// One 10 ms world motion tick: how the feet move, for the world (frame.hpp).
  TickMotion tick(api::Blackboard& blackboard);

  const WalkEngine& engine() const { return *engine_; }
  /// The WalkCycle and kick of an engine of ours; std::logic_error for a foreign engine.
  const WalkCycle& walk() const;
  const KickGenerator& kick() const;
  float head_yaw() const { return yaw_; }
  float head_pitch() const { return pitch_; }

  /// Engine ticks run so far.
  int64_t engine_ticks() const { return engine_ticks_; }
  /// Both feet after the last world tick (odometry frame).
  const FeetPose& feet() const { return feet_; }
  /// What the engine was given at its last tick.
  const nao::Sensors& sensors() const { return sensors_; }
  /// The stance sole of a joint engine (JointFeet); the left for a feet engine.
  nao::Side stance() const { return joint_feet_.stance(); }
  /// Whether a bad output stopped the engine.
  bool engine_stopped() const { return stopped_; }

 private:
  /// The feet and the odometry at one instant.
  struct Sample {
    FeetPose feet;
    Pose2D odometry;
  };

  void tick_head(const api::ActionCommand::Head& request);
  void tick_engine(const api::ActionCommand::Body& body, bool fallen);
  /// The sample an output gives, or nothing (after the warning) for a bad one.
  bool accept(const WalkEngineOutput& out, Sample& sample);
  Sample sample_at(int64_t utime) const;

  std::unique_ptr<WalkEngine> engine_;
  MotionDef def_;
  int64_t period_us_ = kMotionTickUs;
  nao::JointFeet joint_feet_;
  nao::Sensors sensors_;
  WalkEngineOutput output_;
  WalkEngineStatus status_;
  Sample previous_, current_;   ///< the engine's last two samples, at sample_us_ - period and sample_us_
  int64_t sample_us_ = 0;       ///< engine clock: time of the current sample
  int64_t world_us_ = 0;        ///< world clock: end of the last world tick
  int64_t engine_ticks_ = 0;
  bool stopped_ = false;
  FeetPose feet_; ///< both feet after the last world tick
  float yaw_ = 0, pitch_ = 0;
};

} // namespace touchline::robot
