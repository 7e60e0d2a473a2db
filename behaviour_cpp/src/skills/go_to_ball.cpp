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
  const AbsCoord& ball = blackboard.localisation.ballPos;
  const FieldPointExact aim = kickAim(ball.x, ball.y, goalX_, goalY_, behind_);
  if (learned_) {
    const FieldPose target = pointBehindBallExact(ball, aim.x, aim.y, behind_);
    learned_->setTarget(target.x, target.y, target.theta);
    return learned_->tick(blackboard);
  }
  const AbsCoord target =
      pointBehindBall(ball, static_cast<float>(aim.x), static_cast<float>(aim.y), behind_);
  goToPose_.setTarget(target.x, target.y, target.theta);
  return goToPose_.tick(blackboard);
}

} // namespace touchline::behaviour::skills
