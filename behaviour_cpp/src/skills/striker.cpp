#include "touchline/behaviour/skills/striker.hpp"

namespace touchline::behaviour::skills {

using namespace api;

Striker::Striker(const std::optional<std::string>& policy)
    : kick_(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, false, std::nullopt, policy, true) {}

ActionCommand::All Striker::tick(const Blackboard& blackboard) { return kick_.tick(blackboard); }

} // namespace touchline::behaviour::skills
