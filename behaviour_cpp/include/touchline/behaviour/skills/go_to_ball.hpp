#pragma once
// GoToBall: walk to BEHIND_BALL_DIST behind the ball, facing the goal, or along the line a
// ball on it lies on (ball.hpp's kickAim) (via GoToPose, or LearnedGoToPose when given a policy); the port of behaviour_py/skills/go_to_ball.py. Uses
// localisation.ballPos while the ball was seen recently; otherwise stands, leaving the head
// to search.
#include <optional>
#include <string>

#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/learned_go_to_pose.hpp"

namespace touchline::behaviour::skills {

class GoToBall : public api::Behaviour {
 public:
  /// goalX, goalY: the goal to face (mm); behind: robot-to-ball distance (mm); policy:
  /// nullopt to walk with GoToPose, else the learned policy's file (data-relative) to walk
  /// with LearnedGoToPose. Throws BehaviourError for a bad policy file.
  explicit GoToBall(float goalX = OPPONENT_GOAL_X, float goalY = OPPONENT_GOAL_Y, float behind = BEHIND_BALL_DIST,
                    const std::optional<std::string>& policy = std::nullopt);
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  const GoToPose& goToPose() const { return goToPose_; }
  /// The learned walker, if this GoToBall walks with one.
  const std::optional<LearnedGoToPose>& learnedGoToPose() const { return learned_; }

 private:
  float goalX_, goalY_, behind_;
  GoToPose goToPose_;
  std::optional<LearnedGoToPose> learned_; ///< set: walks with it instead of goToPose_
};

} // namespace touchline::behaviour::skills
