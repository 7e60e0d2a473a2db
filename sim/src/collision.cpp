#include "touchline/sim/collision.hpp"

#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::sim {

namespace {

/// Distance of `p` ahead of the coronal plane of `robot` (+ in front of it).
float ahead_of(const Pose2D& robot, const Pose2D& p) {
  return (p.x_mm - robot.x_mm) * std::cos(robot.theta_rad) + (p.y_mm - robot.y_mm) * std::sin(robot.theta_rad);
}

float distance(const Pose2D& p, float x, float y) { return std::hypot(p.x_mm - x, p.y_mm - y); }

/// How far `robot`'s heading is from pointing at `other`, radians.
float aim_error(const Pose2D& robot, const Pose2D& other) {
  const float bearing = std::atan2(other.y_mm - robot.y_mm, other.x_mm - robot.x_mm);
  return std::fabs(normalise_angle(bearing - robot.theta_rad));
}

} // namespace

bool facing_same_way(float theta_a_rad, float theta_b_rad) {
  return std::fabs(normalise_angle(theta_a_rad - theta_b_rad)) < kPi / 2;
}

bool in_front_of(const Pose2D& a, const Pose2D& b) {
  // dist_from_line1 (b to a's plane) > dist_from_line2 (a to b's plane) means a is behind.
  return !(ahead_of(a, b) > ahead_of(b, a));
}

CollisionVerdict judge_collision(const CollisionDef& def, const Pose2D& a, const Pose2D& b, float ball_x_mm,
                                 float ball_y_mm) {
  CollisionVerdict verdict;
  if (std::hypot(a.x_mm - b.x_mm, a.y_mm - b.y_mm) >= def.contact_distance_mm) return verdict;
  verdict.same_way = facing_same_way(a.theta_rad, b.theta_rad);
  const float da = distance(a, ball_x_mm, ball_y_mm), db = distance(b, ball_x_mm, ball_y_mm);
  if (da < def.contest_distance_mm && db < def.contest_distance_mm) {
    verdict.kind = Collision::kContesting;
    verdict.stopped = da <= db ? 1 : 0;
    return verdict;
  }
  verdict.kind = Collision::kPushing;
  if (verdict.same_way) {
    verdict.pusher = in_front_of(a, b) ? 1 : 0;
  } else {
    verdict.pusher = aim_error(a, b) <= aim_error(b, a) ? 0 : 1;
  }
  return verdict;
}

float speed_towards(const Pose2D& from, const BodyVelocity& v, const Pose2D& to) {
  const float dx = to.x_mm - from.x_mm, dy = to.y_mm - from.y_mm;
  const float d = std::hypot(dx, dy);
  if (d <= 0.f) return 0.f; // on top of each other: no direction to walk in
  return (v.x_mm_s * dx + v.y_mm_s * dy) / d;
}

bool steps_towards(const Pose2D& body, const TickMotion& motion, const Pose2D& to) {
  const float dx = (motion.left.dx_mm + motion.right.dx_mm) / 2, dy = (motion.left.dy_mm + motion.right.dy_mm) / 2;
  const float c = std::cos(body.theta_rad), s = std::sin(body.theta_rad);
  return speed_towards(body, BodyVelocity{c * dx - s * dy, s * dx + c * dy}, to) > 0.f;
}

int walking_pusher(const CollisionVerdict& verdict, const Pose2D& a, const BodyVelocity& va, const Pose2D& b,
                   const BodyVelocity& vb, float walking_into_mm_s) {
  if (verdict.kind != Collision::kPushing) return -1;
  const bool a_walks_in = speed_towards(a, va, b) > walking_into_mm_s;
  const bool b_walks_in = speed_towards(b, vb, a) > walking_into_mm_s;
  const bool thesis_walks_in = verdict.pusher == 0 ? a_walks_in : b_walks_in;
  const bool other_walks_in = verdict.pusher == 0 ? b_walks_in : a_walks_in;
  if (thesis_walks_in) return verdict.pusher;
  if (other_walks_in) return 1 - verdict.pusher;
  return -1;
}

} // namespace touchline::sim
