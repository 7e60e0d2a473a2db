#pragma once
// GoToBall: walk to BEHIND_BALL_DIST behind the ball, facing the goal (via GoToPose); the
// port of behaviour_py/skills/go_to_ball.py. Uses localisation.ballPos while the ball was
// seen recently; otherwise stands, leaving the head to search.
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"

namespace touchline::behaviour::skills {

class GoToBall : public api::Behaviour {
 public:
  /// goalX, goalY: the goal to face (mm); behind: robot-to-ball distance (mm).
  explicit GoToBall(float goalX = OPPONENT_GOAL_X, float goalY = OPPONENT_GOAL_Y, float behind = BEHIND_BALL_DIST);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  const GoToPose& goToPose() const { return goToPose_; }

 private:
  float goalX_, goalY_, behind_;
  GoToPose goToPose_;
};

} // namespace touchline::behaviour::skills
