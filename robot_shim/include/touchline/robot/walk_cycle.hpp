#pragma once
// WalkCycle: an omnidirectional, Fast-Walk style, open-loop gait generator (thesis
// 2.2.2). Every 10 ms motion tick it advances the gait phase t within the period T and
// computes both feet's poses; the world moves each foot by the displacement between two
// ticks. Reads: the requested body velocity. Writes: feet poses and odometry.
//
// How it walks:
// - The request is clamped to the speed limits; velocity() follows it at most accel*dt
//   per tick per axis. A planned body pose integrates velocity() every tick.
// - A cycle of T seconds is a left step (phase [0, T/2)) then a right step
//   ([T/2, T)). When stepping starts from standing the first step is taken by the foot
//   on the side of travel: the right foot (phase starts at T/2) when the request goes
//   right, or, with no sideways part, turns clockwise; otherwise the left foot.
// - At each step's start the walk predicts the planned body pose and velocity at the
//   step's end (assuming the request holds) and lands the swing foot there, offset to
//   its side by foot_separation/2 and half a step (velocity * T/4) ahead. The stance
//   foot never moves; the swing foot moves only in the single-support part of the step.
//   Steady walking therefore moves each foot velocity * T per cycle (150 mm at
//   300 mm/s, T = 0.5 s) and the body exactly velocity * T per cycle.
// - The body pose (odometry) is the midpoint of the feet and their mean heading.
// - A zero request decelerates, lands the feet side by side (square, at
//   foot_separation_mm around the planned pose) and then stands still.
#include <string>

#include "touchline/frame.hpp"

namespace touchline::robot {

/// Walk parameters, read from config/walk.ini (thesis 2.5 asks for user-set walks).
struct WalkDef {
  float period_s = 0.5f;             ///< T: full gait cycle, one step of each foot, seconds
  float max_forward_mm_s = 300.f;    ///< forward speed limit
  float max_backward_mm_s = 200.f;   ///< backward speed limit
  float max_left_mm_s = 200.f;       ///< sideways speed limit, either side
  float max_turn_rad_s = 1.5f;       ///< turn rate limit, either way
  float accel_forward_mm_s2 = 600.f; ///< forward/backward acceleration limit
  float accel_left_mm_s2 = 600.f;    ///< sideways acceleration limit
  float accel_turn_rad_s2 = 4.f;     ///< turn acceleration limit
  float foot_separation_mm = 100.f;  ///< lateral distance between foot centres when standing
  float double_support = 0.2f;       ///< fraction of each step with both feet on the ground, [0, 0.9]
  float swing_shape = 1.f;           ///< 0: constant-speed swing, 1: cosine ease in and out
};

/// Reads a WalkDef from an INI file ([walk] section). Throws touchline::ConfigError.
WalkDef load_walk_def(const std::string& path);

/// Requested body velocity; clamped to the WalkDef limits by the walk.
struct WalkRequest {
  float forward_mm_s = 0; ///< + forward
  float left_mm_s = 0;    ///< + left
  float turn_rad_s = 0;   ///< + counter-clockwise
};

/// The step the thesis's WalkCycle is given: per-step sizes (mm, rad) for one step,
/// measured from the swing foot's lift-off pose to its landing pose in the body frame at
/// the step's start. The stance foot does not move, so its forward travel is 0. Steady
/// walking at 300 mm/s with T = 0.5 s gives the swing foot 150 mm a step.
struct StepParams {
  float forward_left_mm = 0;  ///< ForwardL: forward travel of the left foot over the step
  float forward_right_mm = 0; ///< ForwardR: forward travel of the right foot over the step
  float left_mm = 0;          ///< Left: sideways travel of the swing foot over the step
  float turn_rad = 0;         ///< Turn: rotation of the swing foot over the step
};

/// Both feet in the odometry frame (the frame the walk started in).
struct FeetPose {
  Pose2D left;
  Pose2D right;
};

class WalkCycle {
 public:
  explicit WalkCycle(const WalkDef& def = {});

  /// Standing, feet side by side at foot_separation_mm around the odometry origin.
  void reset();

  /// Advances one motion tick of dt_s seconds towards `request` (after speed and
  /// acceleration limits). A zero request finishes the current step, brings the feet
  /// together and stands; standing, the feet do not move.
  void tick(const WalkRequest& request, float dt_s);

  const FeetPose& feet() const { return feet_; }
  /// Midpoint of the feet and their mean heading: the body pose the world also uses.
  Pose2D odometry() const;
  /// Body velocity after limits, as of the last tick.
  const WalkRequest& velocity() const { return velocity_; }
  /// Parameters of the step in progress.
  const StepParams& step() const { return step_; }
  /// t: time into the current gait cycle, in [0, period_s).
  float phase_s() const { return phase_s_; }
  bool standing() const { return standing_; }
  bool left_swinging() const { return left_swing_; }
  const WalkDef& def() const { return def_; }

  /// Standing, feet side by side around `body` (odometry frame): where a motion that is
  /// not a step (a dive) left the robot; the walk goes on from there.
  void stand_at(const Pose2D& body);
  /// Feet at rest around `body`: side by side, square, foot_separation_mm apart.
  FeetPose feet_at_rest(const Pose2D& body) const;

 private:
  WalkDef def_;
  FeetPose feet_;
  WalkRequest velocity_;
  StepParams step_;
  float phase_s_ = 0;
  bool standing_ = true;
  bool left_swing_ = true;
  Pose2D planned_;          ///< body pose the walk aims for: velocity_ integrated
  Pose2D lift_off_;         ///< swing foot's pose at the start of the step
  Pose2D landing_;          ///< swing foot's pose at the end of the step
  float step_time_s_ = 0;   ///< time into the current step, [0, period_s / 2)

  float step_duration_s() const { return 0.5f * def_.period_s; }
  Pose2D& swing_foot() { return left_swing_ ? feet_.left : feet_.right; }
  /// Leaves standing, the first step taken by the foot on the side of travel.
  void start_walking(const WalkRequest& target, float dt_s);
  /// Plans the step now starting: landing pose and StepParams.
  void begin_step(const WalkRequest& target, float dt_s);
  /// Moves the swing foot to where it is `step_time_s_` into the step.
  void move_swing_foot();
  bool feet_at_rest_around_plan() const;
  void stand();
};

/// Motion of each foot between two poses, in the body frame of `before` (see FootMotion).
void feet_motion(const FeetPose& before, const FeetPose& after, FootMotion& left, FootMotion& right);

} // namespace touchline::robot
