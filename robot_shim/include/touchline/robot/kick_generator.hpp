#pragma once
// KickGenerator: the kick and the dribble (thesis 2.2.3), hard coded as on the thesis's
// simulator and tuned in config/kick.ini. Both run three phases:
// - prepare: the walk is brought to a stop (it decelerates and lands the feet square),
//   then the robot stands still for prepare_s (on the robot: the weight shift).
// - swing: the kicking foot turns to `bend` while drawing back by backswing_mm (wind-up),
//   strikes forward along the body x rotated by `bend` to swing_length_mm in front of
//   where it started, then returns to exactly its start pose. The other foot stays still.
// - recover: both feet stand still for recover_s; then the generator is done.
// The generator moves feet only: the ball moves because the swinging foot, a Box2D body
// driven at displacement / dt, hits it. Reads: the latched Body request. Writes: feet poses.
#include <string>

#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot_api/action_command.hpp"

namespace touchline::robot {

/// One swing motion (a kick or a dribble): a section of config/kick.ini. Distances along
/// the swing direction (body x rotated by bend), from the kicking foot's start pose.
struct SwingDef {
  float prepare_s = 0.4f;             ///< standing still after the walk stops, s (at least one tick)
  float backswing_mm = 60.f;          ///< wind-up: the foot first draws back this far, mm
  float swing_length_mm = 120.f;      ///< the strike ends this far in front of the start, mm
  float peak_speed_mm_s = 1600.f;     ///< foot speed at the middle of the strike at power 1, mm/s
  float min_power = 0.1f;             ///< lower powers swing at this power (bounds the strike's time)
  float reposition_speed_mm_s = 400.f;///< peak foot speed of the wind-up and the return, mm/s
  float aim_speed_rad_s = 3.f;        ///< peak turn rate of the foot turning to bend and back, rad/s
  float max_bend_rad = 0.6f;          ///< |bend| is clamped to this, rad
  float recover_s = 0.4f;             ///< standing still after the swing, s (at least one tick)
};

/// The dribble's defaults: less power, quicker (thesis 2.2.3).
inline SwingDef default_dribble_def() {
  SwingDef d;
  d.prepare_s = 0.1f;
  d.backswing_mm = 20.f;
  d.swing_length_mm = 100.f;
  d.peak_speed_mm_s = 900.f;
  d.min_power = 0.1f;
  d.reposition_speed_mm_s = 500.f;
  d.aim_speed_rad_s = 3.f;
  d.max_bend_rad = 0.6f;
  d.recover_s = 0.1f;
  return d;
}

/// The [kick] and [dribble] sections of config/kick.ini.
struct KickDef {
  SwingDef kick;
  SwingDef dribble = default_dribble_def();
};

/// Reads a KickDef from an INI file ([kick], [dribble]); "" gives the defaults. Throws
/// touchline::ConfigError, one line naming the file and the key.
KickDef load_kick_def(const std::string& path);

/// kickPhase on the MotionBlackboard.
enum class KickPhase : int { kNone = 0, kPrepare = 1, kSwing = 2, kRecover = 3 };

/// A swing planned in 10 ms ticks: wind-up, strike, return. Each segment eases in and out
/// (cosine), so a move of D mm over n ticks peaks at pi * D / (2 * n * dt).
struct SwingPlan {
  float bend_rad = 0;          ///< swing direction from the body x, after clamping, rad
  float backswing_mm = 0;
  float swing_length_mm = 0;
  float strike_speed_mm_s = 0; ///< the strike's requested peak foot speed (power-scaled)
  int windup_ticks = 0;        ///< draw back by backswing_mm and turn to bend (0 if neither)
  int strike_ticks = 1;        ///< from -backswing_mm to +swing_length_mm
  int return_ticks = 1;        ///< back to the start pose, turning square again
  int total_ticks() const { return windup_ticks + strike_ticks + return_ticks; }
};

/// Plans a swing of `def` at `power` ([0, 1], raised to min_power) towards `bend` (rad).
SwingPlan plan_swing(const SwingDef& def, float power, float bend_rad);

/// The kicking foot `tick` ticks into the swing (0 = start, total_ticks() = back at the
/// start): its travel along the swing direction (mm) and its turn (rad), both exactly 0
/// at either end.
struct SwingOffset {
  float along_mm = 0;
  float turn_rad = 0;
};
SwingOffset swing_offset(const SwingPlan& plan, int tick);

/// Ticks a duration lasts: rounded, at least one.
int duration_ticks(float seconds);

class KickGenerator {
 public:
  explicit KickGenerator(const KickDef& def = {});

  /// Latches `body` (actionType KICK or DRIBBLE: its power, bend and foot) and enters
  /// prepare. A running kick ignores this: it always runs to completion.
  void start(const api::ActionCommand::Body& body);
  bool running() const { return phase_ != KickPhase::kNone; }
  /// Stops the kick at once (the robot was picked up): not running from now on.
  void cancel() { phase_ = KickPhase::kNone; }

  /// One 10 ms tick of the running kick; `walk` is the walk it interrupts (ticked with
  /// no request until it stands, then left standing). Returns both feet after the tick,
  /// in the walk's odometry frame. When the recover phase ends the kick stops running
  /// and the feet are exactly the walk's again.
  FeetPose tick(WalkCycle& walk);

  /// Phase the last tick ran in (kNone before the first).
  KickPhase last_phase() const { return last_phase_; }
  /// The latched request.
  const api::ActionCommand::Body& request() const { return request_; }
  /// The swing planned for the latched request.
  const SwingPlan& plan() const { return plan_; }
  /// Ticks run in the current phase (in the swing: 0 .. plan().total_ticks()).
  int ticks_in_phase() const { return ticks_in_phase_; }
  const KickDef& def() const { return def_; }

 private:
  const SwingDef& swing_def() const;
  /// The feet `swing_tick_` ticks into the swing.
  FeetPose swing_feet() const;

  KickDef def_;
  api::ActionCommand::Body request_;
  SwingPlan plan_;
  KickPhase phase_ = KickPhase::kNone;
  KickPhase last_phase_ = KickPhase::kNone;
  int ticks_in_phase_ = 0;
  FeetPose swing_start_;        ///< the walk's feet, standing, when the swing began
  float swing_heading_rad_ = 0; ///< body heading (odometry frame) the swing direction is relative to
};

} // namespace touchline::robot
