#pragma once
// Stand: the body skill that does nothing (for head-only skills); the port of
// behaviour_py/skills/stand.py.
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour::skills {

class Stand : public api::Behaviour {
 public:
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
};

} // namespace touchline::behaviour::skills
