#include "world_legs.hpp"

#include <algorithm>
#include <cmath>

#include "box2d_units.hpp"

namespace touchline::sim::detail {

namespace {

/// A foot's turn counts as this much travel at its toe when telling the lifted foot, mm/rad.
constexpr float kFootTurnRadius_mm = 80.f;
/// A foot commanded to travel less than this in a tick stands (the solver's and a joint
/// walk's jitter), mm.
constexpr float kLiftedTravel_mm = 0.01f;

/// A foot's pose after its velocity command for one tick.
Pose2D after_command(const FootVelocity& c) {
  const Pose2D now = pose_of(*c.foot);
  return Pose2D{now.x_mm + to_mm(c.linear.x) * kMotionTick_s, now.y_mm + to_mm(c.linear.y) * kMotionTick_s,
                normalise_angle(now.theta_rad + c.angular * kMotionTick_s)};
}

} // namespace

void add_rope(b2World& world, const Legs& legs, float max_foot_spread_mm) {
  b2DistanceJointDef rope;
  rope.Initialize(legs.left, legs.right, legs.left->GetPosition(), legs.right->GetPosition());
  rope.minLength = 0.f; // Box2D raises it to its linear slop: the feet may pass each other
  rope.maxLength = to_m(max_foot_spread_mm);
  rope.stiffness = rope.damping = 0.f; // no spring: only the limit acts
  world.CreateJoint(&rope);
}

void return_to_stance(const PhysicsDef& physics, const Legs& legs, const TickMotion& m, FootVelocity& left,
                      FootVelocity& right) {
  if (physics.stance_return_mm_s <= 0 && physics.stance_return_rad_s <= 0) return;
  const auto travel = [](const FootMotion& f) {
    return std::hypot(f.dx_mm, f.dy_mm) + kFootTurnRadius_mm * std::fabs(f.dtheta_rad);
  };
  const float left_travel = travel(m.left), right_travel = travel(m.right);
  if (std::max(left_travel, right_travel) < kLiftedTravel_mm) return; // standing, or both feet still
  const bool left_lifted = left_travel > right_travel;
  FootVelocity& lifted = left_lifted ? left : right;
  const FootVelocity& standing = left_lifted ? right : left;
  // Where the walk put the lifted foot in the standing one's frame, set on the standing foot.
  const Pose2D& walk_lifted = left_lifted ? legs.walk_left : legs.walk_right;
  const Pose2D& walk_standing = left_lifted ? legs.walk_right : legs.walk_left;
  const b2Vec2 offset = rotate(-walk_standing.theta_rad, b2Vec2(walk_lifted.x_mm - walk_standing.x_mm,
                                                                 walk_lifted.y_mm - walk_standing.y_mm));
  const Pose2D base = after_command(standing);
  const b2Vec2 placed = rotate(base.theta_rad, offset);
  const Pose2D at = after_command(lifted);
  b2Vec2 error(base.x_mm + placed.x - at.x_mm, base.y_mm + placed.y - at.y_mm);
  const float max_mm = physics.stance_return_mm_s * kMotionTick_s;
  if (error.Length() > max_mm) error *= max_mm / error.Length();
  const float max_rad = physics.stance_return_rad_s * kMotionTick_s;
  const float turn_error = base.theta_rad + walk_lifted.theta_rad - walk_standing.theta_rad - at.theta_rad;
  const float turn = std::clamp(normalise_angle(turn_error), -max_rad, max_rad);
  lifted.linear += to_m(error.x / kMotionTick_s, error.y / kMotionTick_s);
  lifted.angular += turn / kMotionTick_s;
}

void hold_twist(const PhysicsDef& physics, const Legs& legs) {
  constexpr float kSolverSlack_rad = 1e-4f; // the solver's rounding on an untouched foot: no correction
  constexpr float kLegTwistLimit_rad = 1.15f;
  const float twist = normalise_angle(legs.right->GetAngle() - legs.left->GetAngle());
  const float walk_twist = std::min(std::fabs(legs.walk_twist_rad()), kLegTwistLimit_rad);
  const float bound = std::max(physics.max_foot_twist_rad, walk_twist);
  if (std::fabs(twist) <= bound + kSolverSlack_rad) return;
  const float excess = 0.5f * (twist - std::copysign(bound, twist));
  legs.left->SetTransform(legs.left->GetPosition(), legs.left->GetAngle() + excess);
  legs.right->SetTransform(legs.right->GetPosition(), legs.right->GetAngle() - excess);
}

} // namespace touchline::sim::detail
