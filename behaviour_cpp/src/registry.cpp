#include "touchline/behaviour/registry.hpp"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <set>

#include "touchline/behaviour/walk_skills.hpp"

namespace touchline::behaviour {

namespace {

/// Reads numeric parameters, rejecting unknown keys and malformed numbers.
class ParamReader {
 public:
  ParamReader(const std::string& behaviour, const Params& params) : behaviour_(behaviour), params_(params) {}

  float number(const std::string& key, float fallback) {
    known_.insert(key);
    const auto it = params_.find(key);
    if (it == params_.end()) return fallback;
    char* end = nullptr;
    const float value = std::strtof(it->second.c_str(), &end);
    if (it->second.empty() || *end != '\0' || !std::isfinite(value))
      throw BehaviourError(behaviour_ + ": parameter " + key + " must be a number (got '" + it->second + "')");
    return value;
  }

  void reject_unknown() const {
    for (const auto& [key, value] : params_)
      if (!known_.count(key)) throw BehaviourError(behaviour_ + ": unknown parameter '" + key + "'");
  }

 private:
  std::string behaviour_;
  const Params& params_;
  std::set<std::string> known_;
};

struct Entry {
  const char* name;
  const char* help;
  std::function<std::unique_ptr<api::Behaviour>(ParamReader&)> make;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> all = {
      {"stand", "stands still", [](ParamReader&) { return std::make_unique<Stand>(); }},
      {"walk", "walks at a constant velocity: forward (mm/s), left (mm/s), turn (rad/s)",
       [](ParamReader& p) {
         const float forward = p.number("forward", 0), left = p.number("left", 0), turn = p.number("turn", 0);
         return std::make_unique<ConstantWalk>(forward, left, turn);
       }},
      {"goto", "walks to a field pose and stands: x (mm), y (mm), theta (rad)",
       [](ParamReader& p) {
         const float x = p.number("x", 0), y = p.number("y", 0), theta = p.number("theta", 0);
         return std::make_unique<GoToPose>(api::AbsCoord{x, y, theta});
       }},
  };
  return all;
}

} // namespace

std::unique_ptr<api::Behaviour> make_behaviour(const std::string& name, const Params& params) {
  for (const auto& entry : entries()) {
    if (name != entry.name) continue;
    ParamReader reader(name, params);
    auto behaviour = entry.make(reader);
    reader.reject_unknown();
    return behaviour;
  }
  std::string names;
  for (const auto& entry : entries()) names += std::string(names.empty() ? "" : ", ") + entry.name;
  throw BehaviourError("unknown behaviour '" + name + "' (known: " + names + ")");
}

std::vector<std::pair<std::string, std::string>> behaviour_help() {
  std::vector<std::pair<std::string, std::string>> help;
  for (const auto& entry : entries()) help.emplace_back(entry.name, entry.help);
  return help;
}

} // namespace touchline::behaviour
