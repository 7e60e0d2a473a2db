#include "touchline/apps/robot_options.hpp"

#include <filesystem>
#include <sstream>

#include "touchline/apps/behaviour_factory.hpp"
#include "touchline/apps/behaviour_plugin.hpp"
#include "touchline/apps/install_dirs.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/cli.hpp"
#include "touchline/ini.hpp"
#include "touchline/python/python_behaviour.hpp"
#include "touchline/python/runswift/profile.hpp"
#include "touchline/robot/walk_engines.hpp"
#include "touchline/robot_api/data.hpp"

namespace po = boost::program_options;

namespace touchline::apps {

namespace {

behaviour::Params parse_params(const std::vector<std::string>& assignments) {
  behaviour::Params params;
  for (const std::string& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0) throw po::error("--param must be key=value (got '" + a + "')");
    params[a.substr(0, eq)] = a.substr(eq + 1);
  }
  return params;
}

/// --walk-engine's help: the engines this build has.
std::string walk_engine_help() {
  std::string names;
  for (const std::string& name : robot::walk_engine_names()) names += (names.empty() ? "" : ", ") + name;
  return "the walk engine, one of " + names + ": walkcycle is our WalkCycle planning the feet every 10 ms; "
         "nao-joints the same plan as a Nao V6's joint angles through our inverse kinematics, back to feet by "
         "forward kinematics; runswift (a build with -DTOUCHLINE_RUNSWIFT_DIR) rUNSWift's own Walk2014Generator "
         "at 12.2 ms";
}

} // namespace

RobotOptions::RobotOptions() : data_dir(api::data_dir()) {
  def.behaviour.python_dir = TOUCHLINE_PYTHON_DIR;
  // An installed program (cmake --install, pip install .) plays from its prefix's copies, not
  // from the source tree it was built in, which may be gone.
  if (const std::string share = installed_share_dir(); !share.empty()) {
    def.behaviour.python_dir = share + "/behaviour_py";
    data_dir = share + "/config";
  }
}

void add_robot_options(po::options_description& options, RobotOptions& o) {
  robot::RobotDef& def = o.def;
  transport::RobotNodeDef& node = o.node;
  options.add_options()
    ("team", number_option("--team", &def.id.team, 0, 1, /*show_default=*/false)->required(), "team index, 0 or 1")
    ("player", number_option("--player", &def.id.player, 1, kMaxTeamSize, /*show_default=*/false)->required(),
     "player number, 1..7 (and within the world's team size)")
    ("behaviour", po::value(&def.behaviour.name)->default_value(def.behaviour.name),
     "the behaviour to run: a C++ one, or py / py:MODULE for Python (see the list below)")
    ("param", po::value(&o.params)->composing(), "a behaviour parameter, key=value (repeatable)")
    ("behaviour-plugin", po::value(&o.behaviour_plugin)->value_name("PATH"),
     "a team's own C++ behaviour library (a shared library built against the installed robot API, "
     "robot_api/plugin.hpp): --behaviour NAME and --param values go to its factory")
    ("python-dir", po::value(&def.behaviour.python_dir)->default_value(def.behaviour.python_dir),
     "the Python behaviour's folder: first on sys.path, its .py files reloaded when edited")
    ("data-dir", po::value(&o.data_dir)->default_value(o.data_dir),
     "the robot's data directory (learned policies, ...): C++ api::data_path(name) and Python "
     "robot.data_path(name) look there")
    ("charge-cpu", po::bool_switch(&def.timing.charge_cpu),
     "charge the behaviour's CPU time to simulated time: a tick using more than one frame "
     "(33.3 ms) of CPU makes the robot miss frames as on the robot (the last request stays in force)")
    ("walk-config", po::value(&o.files.walk), "walk parameters file ([walk] section); default: the built-in walk")
    ("walk-engine", po::value(&def.engine.name)->default_value(def.engine.name),
     walk_engine_help().c_str())
    ("runswift-config", po::value(&def.engine.runswift_config),
     "--walk-engine runswift: one of their option files (e.g. <clone>/image/home/nao/data/runswift.cfg); its walk "
     "keys override their defaults")
    ("kick-config", po::value(&o.files.kick), "kick and dribble parameters file ([kick], [dribble]); default: the built-in kick")
    ("head-config", po::value(&o.files.head), "head joint limits and speed file ([head]); default: the built-in head")
    ("field-config", po::value(&o.files.field), "the world config whose [field] the robot knows (landmarks for localisation); default: SPL 2011")
    ("perfect-localisation", po::bool_switch(&def.localisation.perfect), "the robot's pose from the truth instead of the filter (the ball still from the camera)")
    ("lcm-url", po::value(&node.lcm_url)->default_value(node.lcm_url),
     "LCM provider URL (opened once at start: a URL LCM cannot open is a usage error)")
    ("secret-file", po::value(&o.secret_file),
     "the match secret (hex) every message is authenticated with; default: $TOUCHLINE_MATCH_SECRET. "
     "Every program of the match needs the same one")
    ("join-timeout", number_option("--join-timeout", &node.join_timeout_s, 0.01, 86400.0),
     "wall seconds to wait for sim_world to accept us, 0.01..86400")
    ("world-timeout", number_option("--world-timeout", &node.world_timeout_s, 0.01, 86400.0),
     "wall seconds of silence from sim_world before exiting, 0.01..86400")
    ("tick-timeout-ms", number_option("--tick-timeout-ms", &o.tick_timeout_ms, int64_t{0}, int64_t{3600000}),
     "Python behaviour: wall time one tick() (with a reload's import) may run, 0..3600000 ms, before it is "
     "interrupted; 0: never (e.g. to debug it with pdb)")
    ("snapshot-every", number_option("--snapshot-every", &node.snapshot_every, 0, 1000000),
     "publish the Blackboard (as the behaviour saw it) on TL_BLACKBOARD_<team>_<player> every N behaviour ticks; 0: never");
}

std::string behaviour_list() {
  std::ostringstream out;
  out << "Behaviours (--behaviour NAME --param key=value ...):\n";
  for (const auto& [name, help] : behaviour::behaviour_help()) out << "  " << name << ": " << help << "\n";
  out << "  py, py:MODULE: the Python behaviour: MODULE.tick(blackboard) from --python-dir (MODULE\n"
         "      defaults to behaviour); --param values reach it as the strings robot.params, with\n"
         "      robot.team and robot.player. Edited .py files there are reloaded while the robot\n"
         "      plays (looked for every 250 ms of wall time). While the module fails to import,\n"
         "      raises in tick() or returns anything but robot.All, the robot stands with its\n"
         "      chest LED magenta (0xff00ff) and the traceback is printed once per change of the files.\n"
         "      A tick() that runs longer than --tick-timeout-ms (a loop that never ends, a call that\n"
         "      blocks) is interrupted where it hangs (touchline.TickTimeout, traceback printed) and\n"
         "      not called again until the files change; the robot stands as above meanwhile.\n"
         "  runswift: a rUNSWift behaviour folder (--python-dir, e.g. a clone's image/home/nao/data/\n"
         "      behaviours), unmodified: its behaviour.py with their robot module, their Blackboard\n"
         "      and BehaviourRequest (docs/runswift_behaviour.md). --param skill=NAME (default Game),\n"
         "      headskill=NAME (HeadCentre), positioning=NAME, broadcast_ms=N (1000: one team message\n"
         "      a second), players_per_team=N (5). FIELD_LENGTH etc. come from --field-config.\n"
         "      Reload, timeout and errors as for py; no behaviour.py: the robot stands until it appears.\n"
         "  --behaviour-plugin PATH --behaviour NAME: NAME made by a team's own library (README, \"Your\n"
         "      own C++ behaviour\"); a missing file, a library without the entry point or built\n"
         "      against another robot API, or a name it refuses: one line, exit status 2.\n";
  return out.str();
}

void finish_robot_options(RobotOptions& o) {
  o.def.behaviour.params = parse_params(o.params);
  try {
    robot::python_module(o.def.behaviour); // "py:" names no module: a usage error
  } catch (const ConfigError& e) {
    throw po::error(std::string("--behaviour ") + e.what());
  }
  // A library's names are its own, but the programs start Python for these: keep them Python's.
  if (!o.behaviour_plugin.empty() && robot::python_module(o.def.behaviour))
    throw po::error("--behaviour-plugin makes C++ behaviours: --behaviour " + o.def.behaviour.name +
                    " names the Python one");
  o.def = robot::load_robot_def(o.files, std::move(o.def));
  try {
    robot::make_walk_engine(o.def.engine, o.def.walk, o.def.kick); // an unknown name: a usage error, now
  } catch (const ConfigError& e) {
    throw po::error(std::string("--walk-engine: ") + e.what());
  }
  if (!std::filesystem::is_directory(o.data_dir)) throw po::error("--data-dir " + o.data_dir + " is not a directory");
}

std::unique_ptr<api::Behaviour> make_robot_behaviour(const RobotOptions& o, const std::string& log_name) {
  if (!o.behaviour_plugin.empty()) {
    api::PluginRequest request;
    request.name = o.def.behaviour.name;
    request.params = o.def.behaviour.params;
    request.team = o.def.id.team;
    request.player = o.def.id.player;
    request.data_dir = o.data_dir;
    return make_plugin_behaviour(o.behaviour_plugin, request);
  }
  python::PythonBehaviourDef python;
  if (robot::python_module(o.def.behaviour)) {
    python.name = log_name;
    python.tick_timeout_us = o.tick_timeout_ms * 1000;
  }
  if (o.def.behaviour.name == "runswift") {
    python::runswift::RunswiftDef runswift;
    runswift.field = o.def.localisation.filters.field; // the field the robot knows (--field-config)
    python::runswift::apply_params(o.def.behaviour.params, runswift);
    runswift.name = python.name;
    python.profile = python::runswift::make_profile(std::move(runswift));
  }
  return make_behaviour(o.def, std::move(python));
}

} // namespace touchline::apps
