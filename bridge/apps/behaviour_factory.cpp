#include "touchline/apps/behaviour_factory.hpp"

#include "touchline/behaviour/registry.hpp"

namespace touchline::apps {

std::unique_ptr<api::Behaviour> make_behaviour(const robot::RobotDef& def, python::PythonBehaviourDef python) {
  const robot::BehaviourDef& behaviour = def.behaviour;
  const auto module = robot::python_module(behaviour);
  if (!module) return behaviour::make_behaviour(behaviour.name, behaviour.params);
  python.directory = behaviour.python_dir;
  python.module = *module;
  python.params = behaviour.params;
  python.team = def.id.team;
  python.player = def.id.player;
  return std::make_unique<python::PythonBehaviour>(std::move(python));
}

} // namespace touchline::apps
