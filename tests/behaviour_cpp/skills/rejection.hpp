#pragma once
// What the registry says of a behaviour and its parameters, for the tests of bad parameters.
#include <string>

#include "touchline/behaviour/registry.hpp"

namespace touchline::behaviour::test {

/// The one-line error make_behaviour(skill, params) throws, or "accepted".
inline std::string rejection(const std::string& skill, const Params& params) {
  try {
    make_behaviour(skill, params);
  } catch (const BehaviourError& e) {
    return e.what();
  }
  return "accepted";
}

} // namespace touchline::behaviour::test
