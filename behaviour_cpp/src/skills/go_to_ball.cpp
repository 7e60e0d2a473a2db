#include "touchline/behaviour/skills/go_to_ball.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"

namespace touchline::behaviour::skills {

using namespace api;

GoToBall::GoToBall(float goalX, float goalY, float behind) : goalX_(goalX), goalY_(goalY), behind_(behind) {}

ActionCommand::All GoToBall::tick(const Blackboard& blackboard) {
  if (!ballRecentlySeen(blackboard)) return actioncommand::compose({}, actioncommand::stand());
  const AbsCoord target = pointBehindBall(blackboard.localisation.ballPos, goalX_, goalY_, behind_);
  goToPose_.setTarget(target.x, target.y, target.theta);
  return goToPose_.tick(blackboard);
}

} // namespace touchline::behaviour::skills
