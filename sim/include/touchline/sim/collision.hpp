#pragma once
// The collision heuristic of thesis 2.2.4 (Algorithms 2.1 and 2.2, figure 2.5). The world
// models only feet, so pushing between bodies is judged, not simulated: two robots closer
// than a contact distance have collided; the referee then decides who goes on, who is
// stopped and who is penalised for pushing.
#include "touchline/frame.hpp"

namespace touchline::sim {

struct CollisionDef {
  float contact_distance_mm = 300.f;  ///< body centres closer than this have collided
  float contest_distance_mm = 500.f;  ///< both within this of the ball: contesting it
};

/// Algorithm 2.1: true when the two headings differ by less than 90 degrees. (The thesis
/// maps both to [0, 2pi) and subtracts, which calls 5 and 355 degrees "facing each
/// other"; the circular difference here keeps its intent across the seam.)
bool facing_same_way(float theta_a_rad, float theta_b_rad);

/// Algorithm 2.2: true when `a` is in front of `b`: a's distance to b's coronal plane
/// (the plane through b's centre, across its heading) exceeds b's distance to a's.
bool in_front_of(const Pose2D& a, const Pose2D& b);

enum class Collision {
  kNone,             ///< not in contact
  kContesting,       ///< both near the ball: the one nearer it goes on, the other is stopped
  kPushing,          ///< not contesting: `pusher` is penalised
};

struct CollisionVerdict {
  Collision kind = Collision::kNone;
  bool same_way = false; ///< Algorithm 2.1's answer
  int stopped = -1;      ///< kContesting: 0 (a) or 1 (b)
  int pusher = -1;       ///< kPushing: 0 (a) or 1 (b)
};

/// Figure 2.5's decision tree for robots a and b and the ball. Facing the same way, the
/// robot behind pushes the one in front. Facing each other, the pusher is the robot
/// walking more squarely into the other (its heading nearer the line between them).
CollisionVerdict judge_collision(const CollisionDef& def, const Pose2D& a, const Pose2D& b, float ball_x_mm,
                                 float ball_y_mm);

/// A robot's body velocity over the referee's window, field frame, mm/s.
struct BodyVelocity {
  float x_mm_s = 0, y_mm_s = 0;
};

/// The component of `v`, the velocity of a robot at `from`, along the line to `to`, mm/s:
/// + walking into it, - moving away, 0 standing or passing square to it.
float speed_towards(const Pose2D& from, const BodyVelocity& v, const Pose2D& to);

/// Whether one tick of `motion` (body frame) moves a robot at `body` towards `to`: the feet's
/// mean step has a component along the line to it. A robot that lost a ball contest may
/// not (the thesis' stop), but may step away or aside, so the loser can leave the scrum.
bool steps_towards(const Pose2D& body, const TickMotion& motion, const Pose2D& to);

/// The SPL's reading of a kPushing verdict (rules.pushing_model = walking_into): the robot
/// that walks into an opponent pushes it; one that stands or backs away does not. Of the
/// pusher the thesis named and the other robot, the first whose speed towards the other
/// exceeds `walking_into_mm_s` is the pusher: the thesis' choice when both walk in (it still
/// decides who is behind or walks more squarely into whom), the other robot when only it
/// walks in (it walked into a robot standing or backing away), nobody (-1) when neither
/// does. Returns 0 (a), 1 (b) or -1.
int walking_pusher(const CollisionVerdict& verdict, const Pose2D& a, const BodyVelocity& va, const Pose2D& b,
                   const BodyVelocity& vb, float walking_into_mm_s);

} // namespace touchline::sim
