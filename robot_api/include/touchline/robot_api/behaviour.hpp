#pragma once
// What a behaviour is: something ticked once per perception frame (30 Hz of simulated
// time) with the const Blackboard, returning the ActionCommand it wants executed.
#include "touchline/robot_api/action_command.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::api {

class Behaviour {
 public:
  virtual ~Behaviour() = default;
  virtual ActionCommand::All tick(const Blackboard& blackboard) = 0;
};

} // namespace touchline::api
