#pragma once
// The behaviour a RobotDef names, made: a C++ one from behaviour_cpp's registry, or the
// Python behaviour. It lives with the programs, above both: the robot library (RobotDef,
// Robot) may not depend on behaviour_cpp or on Python, and behaviour_cpp sees only the
// robot API. Makers that never run Python (the in-process match, learning) call
// behaviour::make_behaviour(def.behaviour.name, def.behaviour.params) directly and so
// need no interpreter.
#include <memory>

#include "touchline/python/python_behaviour.hpp"
#include "touchline/robot/robot_def.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::apps {

/// def.behaviour made for the robot def.id. For "py" / "py:MODULE" the Python behaviour
/// from def.behaviour.python_dir, with def.behaviour.params as robot.params and def.id as
/// robot.team / robot.player; its runtime settings (log name, tick timeout, reload
/// interval, clocks) come from `python`, whose directory, module, params, team and player
/// are replaced. Throws behaviour::BehaviourError (unknown name, bad parameter),
/// ConfigError ("py:" with no module) or python::PythonBehaviourError (no interpreter, no
/// such folder or module).
std::unique_ptr<api::Behaviour> make_behaviour(const robot::RobotDef& def, python::PythonBehaviourDef python = {});

} // namespace touchline::apps
