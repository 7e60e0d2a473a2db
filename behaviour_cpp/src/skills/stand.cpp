#include "touchline/behaviour/skills/stand.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"

namespace touchline::behaviour::skills {

api::ActionCommand::All Stand::tick(const api::Blackboard&) {
  return actioncommand::compose({}, actioncommand::stand());
}

} // namespace touchline::behaviour::skills
