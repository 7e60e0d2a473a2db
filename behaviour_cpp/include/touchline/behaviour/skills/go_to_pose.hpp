#pragma once
// GoToPose: walk to a field pose. Thesis Algorithm 4.3 with the forward-first fix; the port
// of behaviour_py/skills/go_to_pose.py.
//
// Far from the target the robot faces it and walks forward (it walks faster forward than
// sideways), turning as it walks: the forward speed scales with cos^2 of the target's bearing
// (forwardFirstSpeedScale: all of it facing the target, half at 45 degrees, none beyond 90,
// where it turns on the spot); within FORWARD_FIRST_DIST, or wherever that is faster (a
// target behind a robot that must end facing the other way: a defender falling back, facing
// the ball), it runs Algorithm 4.3: turn on the spot while the heading is off by more than
// TURN_FIRST_ANGLE, else walk the forward/left decomposition of the target while turning to
// the target heading.
// Which is faster is estimated from the walk's limits (directTime, forwardFirstTime).
// Arrived (with hysteresis): stand, making way for a robot ahead. A target beyond a line (behind
// a ball on it) is moved to FIELD_EDGE_SLACK beyond it. Every walk goes through Avoid
// (avoid.hpp): around robots, out of the own goal box, on the field, backing off when blocked.
#include "touchline/behaviour/skills/avoid.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour::skills {

inline constexpr float WALK_GAIN = 2.f;                      ///< 1/s: walk request (mm/s) per mm of position error
inline constexpr float TURN_GAIN = 2.f;                      ///< 1/s: turn request (rad/s) per rad of heading error
inline constexpr float FORWARD_FIRST_DIST = 400.f;           ///< mm: beyond this, face the target and walk forward
inline constexpr float FORWARD_FIRST_LEAVE_DIST = 500.f;     ///< mm: back to forward-first only beyond this
inline constexpr float DIRECT_MARGIN_S = 0.25f;              ///< s: Algorithm 4.3 when this much faster (a tie walks forward) ...
inline constexpr float DIRECT_HYSTERESIS_S = 0.5f;           ///< s: ... and kept until forward-first is this much faster
inline constexpr float TURN_FIRST_ANGLE = 45.f * api::kPi / 180.f;  ///< rad: Algorithm 4.3 turns on the spot beyond this (alone, the ball moved 1 % more of the play than at 15, 16 matches)
inline constexpr float ARRIVE_DIST = 40.f;                   ///< mm: arrived within this ...
inline constexpr float ARRIVE_ANGLE = 0.1f;                  ///< rad: ... and this
inline constexpr float LEAVE_DIST = 150.f;                   ///< mm: arrived until pushed beyond this ...
inline constexpr float LEAVE_ANGLE = 0.35f;                  ///< rad: ... or turned beyond this

/// The share of its forward speed forward-first walks at with the target `bearing` rad off
/// its heading: cos^2, none beyond 90 degrees (turning on the spot first whenever it was off by
/// more than 15 degrees, the ball moved 0.9 % less of the play in 16 matches).
float forwardFirstSpeedScale(float bearing);

class GoToPose : public api::Behaviour {
 public:
  /// Target (x, y) in mm and heading theta in rad, field frame; with faceBall the robot
  /// ends facing the ball instead of theta.
  explicit GoToPose(float x = 0.f, float y = 0.f, float theta = 0.f, bool faceBall = false);
  void setTarget(float x, float y, float theta);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  bool arrived() const { return arrived_; }
  bool near() const { return near_; }

 private:
  /// How far (rad, + left) the robot must turn to have its final heading.
  float turnError(const api::Blackboard& blackboard, const api::AbsCoord& pos) const;
  void updateArrived(float distance, float turnError);
  void updateNear(const api::RRCoord& toTarget, float turnError);
  /// Walk at the target, turning to face it, slower the further it is off the heading.
  api::ActionCommand::Body forwardFirst(const api::RRCoord& toTarget) const;
  /// Thesis Algorithm 4.3: the target in the robot frame (runswift angles), walked at
  /// proportional speed while turning to the final heading.
  api::ActionCommand::Body algorithm43(const api::AbsCoord& pos, float turnError) const;

  float x_ = 0, y_ = 0, theta_ = 0;
  bool faceBall_ = false;
  bool arrived_ = false;
  bool near_ = false; ///< running Algorithm 4.3: near, or faster than forward-first
  Avoid avoid_;
};

} // namespace touchline::behaviour::skills
