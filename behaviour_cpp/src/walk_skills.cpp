#include "touchline/behaviour/walk_skills.hpp"

namespace touchline::behaviour {

using namespace api;

ActionCommand::All ConstantWalk::tick(const Blackboard&) {
  ActionCommand::All all;
  all.body = ActionCommand::walk(forward_, left_, turn_);
  return all;
}

} // namespace touchline::behaviour
