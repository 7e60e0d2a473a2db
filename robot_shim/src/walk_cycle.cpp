#include "touchline/robot/walk_cycle.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"

#include "approach.hpp"

namespace touchline::robot {

namespace {

/// A step ends when less than this is left of it (phase sums of dt drift in float).
constexpr float kStepEndSlack_s = 1e-5f;
/// Feet this close to their rest poses count as at rest (float rounding only).
constexpr float kRestTolerance_mm = 1e-3f;
constexpr float kRestTolerance_rad = 1e-5f;

/// `base` moved by (dx, dy) in its own frame and turned by dtheta.
Pose2D compose(const Pose2D& base, float dx_mm, float dy_mm, float dtheta_rad) {
  const float c = std::cos(base.theta_rad), s = std::sin(base.theta_rad);
  return {base.x_mm + c * dx_mm - s * dy_mm, base.y_mm + s * dx_mm + c * dy_mm,
          normalise_angle(base.theta_rad + dtheta_rad)};
}

Pose2D body_of(const FeetPose& feet) {
  return {0.5f * (feet.left.x_mm + feet.right.x_mm), 0.5f * (feet.left.y_mm + feet.right.y_mm),
          mean_heading(feet.left.theta_rad, feet.right.theta_rad)};
}

bool is_zero(const WalkRequest& v) {
  return v.forward_mm_s == 0 && v.left_mm_s == 0 && v.turn_rad_s == 0;
}

/// A NaN or infinite request component (a behaviour bug) asks for nothing on that axis.
float finite_or_zero(float value) { return std::isfinite(value) ? value : 0.f; }

WalkRequest clamp_to_limits(const WalkRequest& request, const WalkDef& def) {
  return {std::clamp(finite_or_zero(request.forward_mm_s), -def.max_backward_mm_s,
                     def.max_forward_mm_s),
          std::clamp(finite_or_zero(request.left_mm_s), -def.max_left_mm_s, def.max_left_mm_s),
          std::clamp(finite_or_zero(request.turn_rad_s), -def.max_turn_rad_s, def.max_turn_rad_s)};
}

/// One tick of the acceleration limits: each axis moves towards `target` independently.
WalkRequest accelerate(const WalkRequest& v, const WalkRequest& target, const WalkDef& def,
                       float dt_s) {
  return {approach(v.forward_mm_s, target.forward_mm_s, def.accel_forward_mm_s2 * dt_s),
          approach(v.left_mm_s, target.left_mm_s, def.accel_left_mm_s2 * dt_s),
          approach(v.turn_rad_s, target.turn_rad_s, def.accel_turn_rad_s2 * dt_s)};
}

/// Moves `pose` over one tick whose velocity goes linearly from v0 to v1 (trapezoid rule,
/// translation taken along the mid-tick heading), so a ramp from rest to v over time
/// t_a covers exactly v * t_a / 2.
Pose2D integrate(const Pose2D& pose, const WalkRequest& v0, const WalkRequest& v1, float dt_s) {
  const float dtheta = 0.5f * (v0.turn_rad_s + v1.turn_rad_s) * dt_s;
  const Pose2D mid_heading{pose.x_mm, pose.y_mm, pose.theta_rad + 0.5f * dtheta};
  Pose2D moved = compose(mid_heading, 0.5f * (v0.forward_mm_s + v1.forward_mm_s) * dt_s,
                         0.5f * (v0.left_mm_s + v1.left_mm_s) * dt_s, 0);
  moved.theta_rad = normalise_angle(pose.theta_rad + dtheta);
  return moved;
}

/// Where a foot lands for a body at `body` moving at `v`: half a step (v * half_step_s)
/// ahead of the body and foot_separation/2 to the foot's side.
Pose2D landing_pose(const Pose2D& body, const WalkRequest& v, float half_step_s,
                    float side_offset_mm) {
  const Pose2D ahead = compose(body, v.forward_mm_s * half_step_s, v.left_mm_s * half_step_s,
                               v.turn_rad_s * half_step_s);
  return compose(ahead, 0, side_offset_mm, 0);
}

/// Swing progress in [0, 1] for the fraction s of single support: linear for shape 0,
/// cosine ease in and out for shape 1, a blend in between.
float swing_progress(float s, float shape) {
  const float eased = 0.5f * (1 - std::cos(kPi * s));
  return (1 - shape) * s + shape * eased;
}

Pose2D interpolate(const Pose2D& from, const Pose2D& to, float progress) {
  return {from.x_mm + (to.x_mm - from.x_mm) * progress,
          from.y_mm + (to.y_mm - from.y_mm) * progress,
          normalise_angle(from.theta_rad + normalise_angle(to.theta_rad - from.theta_rad) * progress)};
}

/// `motion` of a pose from `before` to `after`, in the frame of a body at heading theta.
FootMotion motion_in_frame(const Pose2D& before, const Pose2D& after, float theta_rad) {
  const float dx = after.x_mm - before.x_mm, dy = after.y_mm - before.y_mm;
  const float c = std::cos(theta_rad), s = std::sin(theta_rad);
  return {c * dx + s * dy, -s * dx + c * dy, normalise_angle(after.theta_rad - before.theta_rad)};
}

bool near(const Pose2D& a, const Pose2D& b) {
  return std::abs(a.x_mm - b.x_mm) <= kRestTolerance_mm &&
         std::abs(a.y_mm - b.y_mm) <= kRestTolerance_mm &&
         std::abs(normalise_angle(a.theta_rad - b.theta_rad)) <= kRestTolerance_rad;
}

} // namespace

WalkCycle::WalkCycle(const WalkDef& def) : def_(def) { reset(); }

void WalkCycle::reset() {
  planned_ = {};
  stand();
  lift_off_ = landing_ = feet_.left;
}

void WalkCycle::stand_at(const Pose2D& body) {
  planned_ = body;
  stand();
  lift_off_ = landing_ = feet_.left;
}

Pose2D WalkCycle::odometry() const { return body_of(feet_); }

FeetPose WalkCycle::feet_at_rest(const Pose2D& body) const {
  const float half = 0.5f * def_.foot_separation_mm;
  return {compose(body, 0, half, 0), compose(body, 0, -half, 0)};
}

bool WalkCycle::feet_at_rest_around_plan() const {
  const FeetPose rest = feet_at_rest(planned_);
  return near(feet_.left, rest.left) && near(feet_.right, rest.right);
}

void WalkCycle::tick(const WalkRequest& request, float dt_s) {
  if (!(dt_s > 0)) return;
  const WalkRequest target = clamp_to_limits(request, def_);
  if (standing_) {
    if (is_zero(target)) return; // standing still: nothing moves, not even the phase
    start_walking(target, dt_s);
  }

  const WalkRequest before = velocity_;
  velocity_ = accelerate(velocity_, target, def_, dt_s);
  planned_ = integrate(planned_, before, velocity_, dt_s);

  step_time_s_ += dt_s;
  const float step_s = step_duration_s();
  if (step_time_s_ < step_s - kStepEndSlack_s) {
    move_swing_foot();
  } else {
    swing_foot() = landing_; // exactly, so a closing step leaves the feet exactly square
    if (is_zero(target) && is_zero(velocity_) && feet_at_rest_around_plan()) {
      stand();
      return;
    }
    // Carry what the tick had left into the next step (fmod: dt > T/2 stays bounded).
    step_time_s_ = std::fmod(std::max(0.f, step_time_s_ - step_s), step_s);
    left_swing_ = !left_swing_;
    begin_step(target, dt_s);
    move_swing_foot();
  }
  phase_s_ = (left_swing_ ? 0.f : step_s) + step_time_s_;
}

void WalkCycle::start_walking(const WalkRequest& target, float dt_s) {
  standing_ = false;
  // Step first with the foot on the side of travel, so the feet open before they close.
  left_swing_ = target.left_mm_s != 0 ? target.left_mm_s > 0 : target.turn_rad_s >= 0;
  step_time_s_ = 0;
  phase_s_ = left_swing_ ? 0.f : step_duration_s();
  begin_step(target, dt_s);
}

void WalkCycle::begin_step(const WalkRequest& target, float dt_s) {
  // Predict the planned body over the step, as the ticks will move it if the request holds.
  const float step_s = step_duration_s();
  const int ticks = std::max(1, static_cast<int>(std::lround((step_s - step_time_s_) / dt_s)));
  Pose2D body_at_end = planned_;
  WalkRequest v_at_end = velocity_;
  for (int i = 0; i < ticks; ++i) {
    const WalkRequest v_next = accelerate(v_at_end, target, def_, dt_s);
    body_at_end = integrate(body_at_end, v_at_end, v_next, dt_s);
    v_at_end = v_next;
  }

  const float side = (left_swing_ ? 0.5f : -0.5f) * def_.foot_separation_mm;
  lift_off_ = swing_foot();
  landing_ = landing_pose(body_at_end, v_at_end, 0.5f * step_s, side);

  const FootMotion travel = motion_in_frame(lift_off_, landing_, odometry().theta_rad);
  step_.forward_left_mm = left_swing_ ? travel.dx_mm : 0.f;
  step_.forward_right_mm = left_swing_ ? 0.f : travel.dx_mm;
  step_.left_mm = travel.dy_mm;
  step_.turn_rad = travel.dtheta_rad;
}

void WalkCycle::move_swing_foot() {
  // Both feet are down for the first and last double_support/2 of the step.
  const float step_s = step_duration_s();
  const float single_support_s = std::max(1e-6f, (1 - def_.double_support) * step_s);
  const float lift_s = 0.5f * def_.double_support * step_s;
  const float s = std::clamp((step_time_s_ - lift_s) / single_support_s, 0.f, 1.f);
  swing_foot() = interpolate(lift_off_, landing_, swing_progress(s, def_.swing_shape));
}

void WalkCycle::stand() {
  feet_ = feet_at_rest(planned_); // a no-op beyond float rounding: they are already there
  velocity_ = {};
  step_ = {};
  phase_s_ = 0;
  step_time_s_ = 0;
  standing_ = true;
  left_swing_ = true;
}

void feet_motion(const FeetPose& before, const FeetPose& after, FootMotion& left,
                 FootMotion& right) {
  const float body_heading = body_of(before).theta_rad;
  left = motion_in_frame(before.left, after.left, body_heading);
  right = motion_in_frame(before.right, after.right, body_heading);
}

} // namespace touchline::robot
