#include "touchline/behaviour/skills/go_to_ball.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"

namespace touchline::behaviour::skills {

using namespace api;

GoToBall::GoToBall(float goalX, float goalY, float behind, const std::optional<std::string>& policy)
    : goalX_(goalX), goalY_(goalY), behind_(behind) {
  if (policy) learned_.emplace(0.0, 0.0, 0.0, *policy);
}

ActionCommand::All GoToBall::tick(const Blackboard& blackboard) {
  if (!ballRecentlySeen(blackboard)) return actioncommand::compose({}, actioncommand::stand());
  if (learned_) {
    const FieldPose target = pointBehindBallExact(blackboard.localisation.ballPos, goalX_, goalY_, behind_);
    learned_->setTarget(target.x, target.y, target.theta);
    return learned_->tick(blackboard);
  }
  const AbsCoord target = pointBehindBall(blackboard.localisation.ballPos, goalX_, goalY_, behind_);
  goToPose_.setTarget(target.x, target.y, target.theta);
  return goToPose_.tick(blackboard);
}

} // namespace touchline::behaviour::skills
