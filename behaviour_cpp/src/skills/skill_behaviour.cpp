#include "touchline/behaviour/skills/skill_behaviour.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/ball.hpp"

namespace touchline::behaviour::skills {

api::ActionCommand::All SkillBehaviour::tick(const api::Blackboard& blackboard) {
  const api::ActionCommand::Body body = body_->tick(blackboard).body;
  const api::ActionCommand::Head head = head_->tick(blackboard).head;
  const int32_t chest = ballRecentlySeen(blackboard) ? BALL_SEEN_CHEST : BALL_LOST_CHEST;
  return actioncommand::compose(head, body, actioncommand::leds(chest));
}

} // namespace touchline::behaviour::skills
