// robot_shim: one robot's own code (Blackboard, adapters, MotionAdapter, WalkCycle and a
// behaviour) playing in sim_world over LCM. Thin program: options -> Robot -> run_robot.
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include <boost/program_options.hpp>
#include <pybind11/embed.h>

#include "touchline/apps/behaviour_factory.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/cli.hpp"
#include "touchline/ini.hpp"
#include "touchline/lcm/lcm_url.hpp"
#include "touchline/lcm/robot_node.hpp"
#include "touchline/python/python_behaviour.hpp"
#include "touchline/python/runswift/profile.hpp"
#include "touchline/python/tick_guard.hpp"
#include "touchline/robot/walk_engines.hpp"
#include "touchline/robot_api/data.hpp"
#include "touchline/version.hpp"

namespace po = boost::program_options;
using namespace touchline;

namespace {

constexpr int kUsageError = 2;

behaviour::Params parse_params(const std::vector<std::string>& assignments) {
  behaviour::Params params;
  for (const std::string& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0) throw po::error("--param must be key=value (got '" + a + "')");
    params[a.substr(0, eq)] = a.substr(eq + 1);
  }
  return params;
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
         "Stopping: SIGINT or SIGTERM stops the shim within 2 s even while its behaviour hangs\n"
         "(running Python is interrupted; anything else is cut short), exit status 128 + the\n"
         "signal's number (130, 143).\n";
  return out.str();
}

// Stopping on SIGINT/SIGTERM: the node returns at its next look at the flag, and Python
// that runs meanwhile is interrupted (python::request_stop). Whatever still holds the
// shim kStopGraceS later (C++ behaviour code that never returns, Python that swallows the
// interruption, a Python thread that keeps the interpreter from finishing) is cut short
// with _exit; a second signal cuts it short at once. Either way the exit status is the
// conventional 128 + the signal's number (130 for SIGINT, 143 for SIGTERM).

/// Enough for a frame and Python's shutdown; well within a launcher's wait before SIGKILL.
constexpr unsigned kStopGraceS = 2;
volatile std::sig_atomic_t g_stop_signal = 0; ///< the first stop signal's number
char g_grace_message[160] = "robot_shim: still running 2 s after the stop signal; exiting\n";

void on_grace_over(int) {
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, g_grace_message, std::strlen(g_grace_message));
  _exit(128 + g_stop_signal);
}

void on_stop_signal(int signal) {
  if (g_stop_signal != 0) _exit(128 + g_stop_signal);
  g_stop_signal = signal;
  transport::request_robot_stop();
  python::request_stop();
  alarm(kStopGraceS);
}

void handle_stop_signals(int team, int player) {
  std::snprintf(g_grace_message, sizeof g_grace_message,
                "robot_shim %d/%d: still running %u s after the stop signal (stuck in the behaviour?); exiting\n",
                team, player, kStopGraceS);
  struct sigaction action {};
  sigemptyset(&action.sa_mask);
  action.sa_handler = on_grace_over;
  sigaction(SIGALRM, &action, nullptr);
  action.sa_handler = on_stop_signal;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
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

int stop_status() { return 128 + (g_stop_signal ? g_stop_signal : SIGINT); }

} // namespace

int main(int argc, char** argv) {
  // The robot as the command line describes it; load_robot_def reads the files it names.
  robot::RobotDef def;
  def.behaviour.python_dir = TOUCHLINE_PYTHON_DIR;
  robot::RobotConfigFiles files;
  std::string data_dir = api::data_dir();
  std::vector<std::string> param_args;
  std::string secret_file;
  transport::RobotNodeDef node;
  // Far above sim_world's 1000 ms robot timeout, so a slow but finishing tick is the world's
  // to judge; and above what a loaded machine takes to load a large first tick (a 4 MB
  // learned policy took over 2 s with the sanitizer build beside it). The bound is for code
  // that hangs.
  int64_t tick_timeout_ms = 10000;

  po::options_description options(
      "robot_shim: runs one robot's code in a sim_world match over LCM.\n"
      "Usage: robot_shim --team T --player N [options]\nOptions");
  options.add_options()
    ("help,h", "print this help and exit")
    ("version", kVersionHelp)
    ("team", number_option("--team", &def.id.team, 0, 1, /*show_default=*/false)->required(), "team index, 0 or 1")
    ("player", number_option("--player", &def.id.player, 1, kMaxTeamSize, /*show_default=*/false)->required(),
     "player number, 1..7 (and within the world's team size)")
    ("behaviour", po::value(&def.behaviour.name)->default_value(def.behaviour.name),
     "the behaviour to run: a C++ one, or py / py:MODULE for Python (see the list below)")
    ("param", po::value(&param_args)->composing(), "a behaviour parameter, key=value (repeatable)")
    ("python-dir", po::value(&def.behaviour.python_dir)->default_value(def.behaviour.python_dir),
     "the Python behaviour's folder: first on sys.path, its .py files reloaded when edited")
    ("data-dir", po::value(&data_dir)->default_value(data_dir),
     "the robot's data directory (learned policies, ...): C++ api::data_path(name) and Python "
     "robot.data_path(name) look there")
    ("charge-cpu", po::bool_switch(&def.timing.charge_cpu),
     "charge the behaviour's CPU time to simulated time: a tick using more than one frame "
     "(33.3 ms) of CPU makes the robot miss frames as on the robot (the last request stays in force)")
    ("walk-config", po::value(&files.walk), "walk parameters file ([walk] section); default: the built-in walk")
    ("walk-engine", po::value(&def.engine.name)->default_value(def.engine.name),
     walk_engine_help().c_str())
    ("runswift-config", po::value(&def.engine.runswift_config),
     "--walk-engine runswift: one of their option files (e.g. <clone>/image/home/nao/data/runswift.cfg); its walk "
     "keys override their defaults")
    ("kick-config", po::value(&files.kick), "kick and dribble parameters file ([kick], [dribble]); default: the built-in kick")
    ("head-config", po::value(&files.head), "head joint limits and speed file ([head]); default: the built-in head")
    ("field-config", po::value(&files.field), "the world config whose [field] the robot knows (landmarks for localisation); default: SPL 2011")
    ("perfect-localisation", po::bool_switch(&def.localisation.perfect), "the robot's pose from the truth instead of the filter (the ball still from the camera)")
    ("lcm-url", po::value(&node.lcm_url)->default_value(node.lcm_url),
     "LCM provider URL (opened once at start: a URL LCM cannot open is a usage error)")
    ("secret-file", po::value(&secret_file),
     "the match secret (hex) every message is authenticated with; default: $TOUCHLINE_MATCH_SECRET. "
     "Every program of the match needs the same one")
    ("join-timeout", number_option("--join-timeout", &node.join_timeout_s, 0.01, 86400.0),
     "wall seconds to wait for sim_world to accept us, 0.01..86400")
    ("world-timeout", number_option("--world-timeout", &node.world_timeout_s, 0.01, 86400.0),
     "wall seconds of silence from sim_world before exiting, 0.01..86400")
    ("tick-timeout-ms", number_option("--tick-timeout-ms", &tick_timeout_ms, int64_t{0}, int64_t{3600000}),
     "Python behaviour: wall time one tick() (with a reload's import) may run, 0..3600000 ms, before it is "
     "interrupted; 0: never (e.g. to debug it with pdb)")
    ("snapshot-every", number_option("--snapshot-every", &node.snapshot_every, 0, 1000000),
     "publish the Blackboard (as the behaviour saw it) on TL_BLACKBOARD_<team>_<player> every N behaviour ticks; 0: never")
    ("check", "check the options, the config files and the behaviour as for a match and exit (0, or 2 with the "
     "one-line error) without joining one: a C++ behaviour is made with its --param values; for Python only "
     "--python-dir is checked (its module is imported, and its skill read, when the robot plays)");

  std::optional<pybind11::scoped_interpreter> interpreter; // only for py; outlives the behaviour
  std::unique_ptr<api::Behaviour> behaviour;
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n" << behaviour_list();
      return 0;
    }
    if (version_requested(vm, "robot_shim")) return 0;
    po::notify(vm);
    node.key = transport::load_match_key(secret_file);
    def.behaviour.params = parse_params(param_args);
    try {
      robot::python_module(def.behaviour); // "py:" names no module: a usage error
    } catch (const ConfigError& e) {
      throw po::error(std::string("--behaviour ") + e.what());
    }
    def = robot::load_robot_def(files, std::move(def));
    try {
      robot::make_walk_engine(def.engine, def.walk, def.kick); // an unknown name: a usage error, now
    } catch (const ConfigError& e) {
      throw po::error(std::string("--walk-engine: ") + e.what());
    }
    if (!std::filesystem::is_directory(data_dir)) throw po::error("--data-dir " + data_dir + " is not a directory");
    // Before the interpreter: the check redirects stderr for a moment, so no other thread may run.
    if (const auto problem = transport::lcm_url_problem(node.lcm_url))
      throw ConfigError("--lcm-url '" + node.lcm_url + "': cannot open LCM: " + *problem);
    api::set_data_dir(data_dir); // before the behaviour is made: it may load its data
    if (vm.count("check")) {
      if (!robot::python_module(def.behaviour)) apps::make_behaviour(def, {});
      else if (!std::filesystem::is_directory(def.behaviour.python_dir))
        throw po::error("--python-dir " + def.behaviour.python_dir + " is not a directory");
      return 0;
    }
    // From here on a stop signal must reach Python: a module may hang at import.
    handle_stop_signals(def.id.team, def.id.player);
    python::PythonBehaviourDef python;
    if (robot::python_module(def.behaviour)) {
      // Python's own signal handlers stay off: SIGINT/SIGTERM stop the shim (handle_stop_signals); no
      // program directory on sys.path: the behaviour's modules come from --python-dir alone.
      interpreter.emplace(/*init_signal_handlers=*/false, 0, nullptr, /*add_program_dir_to_path=*/false);
      python.name = "robot_shim " + std::to_string(def.id.team) + "/" + std::to_string(def.id.player);
      python.tick_timeout_us = tick_timeout_ms * 1000;
    }
    if (def.behaviour.name == "runswift") {
      python::runswift::RunswiftDef runswift;
      runswift.field = def.localisation.filters.field; // the field the robot knows (--field-config)
      python::runswift::apply_params(def.behaviour.params, runswift);
      runswift.name = python.name;
      python.profile = python::runswift::make_profile(std::move(runswift));
    }
    behaviour = apps::make_behaviour(def, std::move(python));
  } catch (const po::error& e) {
    std::cerr << "robot_shim: " << e.what() << " (see --help)\n";
    return kUsageError;
  } catch (const ConfigError& e) {
    std::cerr << "robot_shim: " << e.what() << "\n";
    return kUsageError;
  } catch (const behaviour::BehaviourError& e) {
    std::cerr << "robot_shim: " << e.what() << "\n";
    return kUsageError;
  } catch (const python::PythonBehaviourError& e) {
    if (g_stop_signal) return stop_status(); // stopped while the module was imported
    std::cerr << "robot_shim: " << e.what() << "\n";
    return kUsageError;
  } catch (const std::invalid_argument& e) { // the match secret
    std::cerr << "robot_shim: " << e.what() << "\n";
    return kUsageError;
  }

  try {
    robot::Robot robot(std::move(def), std::move(behaviour));
    if (g_stop_signal) return stop_status(); // before run_robot, which starts afresh
    switch (transport::run_robot(robot, node, std::cerr)) {
      case transport::RobotExit::kMatchOver: return 0;
      case transport::RobotExit::kRejected: return kUsageError;
      case transport::RobotExit::kNoWorld: return 1;
      case transport::RobotExit::kInterrupted: return stop_status();
    }
  } catch (const std::exception& e) {
    std::cerr << "robot_shim: " << e.what() << "\n";
  }
  return 1;
}
