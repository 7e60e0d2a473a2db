#include "touchline/robot/robot_def.hpp"

#include "touchline/ini.hpp"
#include "touchline/robot/localisation/field_map.hpp"

namespace touchline::robot {

std::optional<std::string> python_module(const BehaviourDef& behaviour) {
  const std::string& name = behaviour.name;
  if (name == "py" || name == "runswift") return std::string("behaviour");
  if (name.rfind("py:", 0) != 0) return std::nullopt;
  if (name.size() == 3) throw ConfigError("py:MODULE needs a module name");
  return name.substr(3);
}

std::string describe(const BehaviourDef& behaviour) {
  std::string text = behaviour.name;
  for (const auto& [key, value] : behaviour.params) text += " " + key + "=" + value;
  return text;
}

RobotDef load_robot_def(const RobotConfigFiles& files, RobotDef def) {
  // Each loader names its file in its errors and bounds every number it reads.
  if (!files.walk.empty()) def.walk = load_walk_def(files.walk);
  if (!files.kick.empty()) def.kick = load_kick_def(files.kick);
  if (!files.head.empty()) def.head = load_head_def(files.head);
  if (!files.field.empty()) def.localisation.filters.field = localisation::load_field_map(files.field);
  return def;
}

} // namespace touchline::robot
