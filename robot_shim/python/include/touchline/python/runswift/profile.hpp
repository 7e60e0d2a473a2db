#pragma once
// The rUNSWift profile of the Python runtime (python_profile.hpp): runs their behaviour
// folder's behaviour.py as their PythonSkill does, unmodified.
// - Before the first import: BEHAVIOUR_ROOT is the folder (where their skill factory looks
//   for skills), which PythonBehaviour puts first on sys.path; LOG_PATH, where their Log
//   module writes, is a fresh temp folder (removed with the profile) unless the user set
//   one; RUNSWIFT_CHECKOUT_DIR is
//   removed, so that their Simulation module (imported first by behaviour.py) leaves
//   sys.path alone.
// - `import robot` gives their API (module.hpp), with the field of the world's config.
// - tick(blackboard) gets their Blackboard (blackboard_builder.hpp) and must return a
//   robot.BehaviourRequest, converted by request_converter.hpp; its shared data is
//   broadcast to the teammates every `broadcast_period_us` (team_message.hpp).
// - No behaviour.py yet: one line, the robot stands and the file is loaded when it appears.
#include <iosfwd>
#include <map>
#include <memory>
#include <string>

#include "touchline/python/python_profile.hpp"
#include "touchline/python/runswift/blackboard_builder.hpp"
#include "touchline/robot/localisation/field_map.hpp"
#include "touchline/python/runswift/request_converter.hpp"

namespace touchline::python::runswift {

struct RunswiftDef {
  robot::localisation::FieldMap field;   ///< FIELD_LENGTH, ...: the field the robot knows (--field-config)
  BlackboardBuilderDef blackboard;       ///< skill names, team numbers, ...
  RunswiftWalkLimits walk;               ///< their walk's limits
  int64_t broadcast_period_us = 1000000; ///< one message a second (their 1 Hz budget); 0: never
  std::string name = "robot";            ///< prefixes log lines
  std::ostream* log = nullptr;           ///< warnings; nullptr: std::cerr
};

/// Reads the --param values the profile takes: skill, headskill, positioning (their
/// names), broadcast_ms (0..60000), players_per_team (1..7). Throws ConfigError naming
/// an unknown key or a bad value.
void apply_params(const std::map<std::string, std::string>& params, RunswiftDef& def);

std::shared_ptr<PythonProfile> make_profile(RunswiftDef def);

} // namespace touchline::python::runswift
