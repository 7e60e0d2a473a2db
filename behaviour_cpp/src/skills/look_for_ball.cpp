#include "touchline/behaviour/skills/look_for_ball.hpp"

#include "touchline/behaviour/skills/ball.hpp"

namespace touchline::behaviour::skills {

api::ActionCommand::All LookForBall::tick(const api::Blackboard& blackboard) {
  if (ballRecentlySeen(blackboard)) {
    headScan_.reset(); // a later search starts from wherever the head is then
    return trackBall_.tick(blackboard);
  }
  return headScan_.tick(blackboard);
}

} // namespace touchline::behaviour::skills
