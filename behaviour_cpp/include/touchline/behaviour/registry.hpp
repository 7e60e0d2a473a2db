#pragma once
// The C++ behaviours, by name, as robot_shim --behaviour NAME --param key=value picks them.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour {

using Params = std::map<std::string, std::string>;

/// A wrong behaviour name or parameter; the message is one line for the user.
struct BehaviourError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Creates the behaviour `name` with `params`. Throws BehaviourError.
std::unique_ptr<api::Behaviour> make_behaviour(const std::string& name, const Params& params);

/// Names and one-line descriptions (with their parameters) for --help.
std::vector<std::pair<std::string, std::string>> behaviour_help();

} // namespace touchline::behaviour
