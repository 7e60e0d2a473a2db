// robot_shim: one robot's own code (Blackboard, adapters, MotionAdapter, WalkCycle and a
// behaviour) playing in sim_world over LCM. Thin program: options -> Robot -> run_robot.
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>

#include <boost/program_options.hpp>
#include <pybind11/embed.h>

#include "touchline/apps/program_log.hpp"
#include "touchline/apps/robot_options.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/ini.hpp"
#include "touchline/lcm/lcm_url.hpp"
#include "touchline/lcm/robot_node.hpp"
#include "touchline/python/python_behaviour.hpp"
#include "touchline/python/tick_guard.hpp"
#include "touchline/robot_api/data.hpp"
#include "touchline/version.hpp"

namespace po = boost::program_options;
using namespace touchline;

namespace {

constexpr int kUsageError = 2;

/// After the behaviours: how the shim stops.
constexpr const char* kStoppingHelp =
    "Stopping: SIGINT or SIGTERM stops the shim within 2 s even while its behaviour hangs\n"
    "(running Python is interrupted; anything else is cut short), exit status 128 + the\n"
    "signal's number (130, 143).\n";

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

int stop_status() { return 128 + (g_stop_signal ? g_stop_signal : SIGINT); }

} // namespace

int main(int argc, char** argv) {
  // The robot as the command line describes it; finish_robot_options reads the files it names.
  apps::RobotOptions robot_options;
  po::options_description options(
      "robot_shim: runs one robot's code in a sim_world match over LCM.\n"
      "Usage: robot_shim --team T --player N [options]\nOptions");
  options.add_options()("help,h", "print this help and exit")("version", kVersionHelp);
  apps::add_robot_options(options, robot_options);
  std::string log_level;
  apps::add_log_level_option(options, log_level);
  options.add_options()
    ("check", "check the options, the config files and the behaviour as for a match and exit (0, or 2 with the "
     "one-line error) without joining one: the behaviour is made with its --param values (a Python module is "
     "imported and its check_params(params) called, if it has one)");
  robot::RobotDef& def = robot_options.def;
  transport::RobotNodeDef& node = robot_options.node;

  std::optional<pybind11::scoped_interpreter> interpreter; // only for py; outlives the behaviour
  std::unique_ptr<api::Behaviour> behaviour;
  std::shared_ptr<spdlog::logger> log = apps::program_log("robot_shim");
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n" << apps::behaviour_list() << kStoppingHelp;
      return 0;
    }
    if (version_requested(vm, "robot_shim")) return 0;
    po::notify(vm);
    apps::set_log_level(*log, log_level);
    node.key = transport::load_match_key(robot_options.secret_file);
    apps::finish_robot_options(robot_options);
    // Before the interpreter: the check redirects stderr for a moment, so no other thread may run.
    if (const auto problem = transport::lcm_url_problem(node.lcm_url))
      throw ConfigError("--lcm-url '" + node.lcm_url + "': cannot open LCM: " + *problem);
    api::set_data_dir(robot_options.data_dir); // before the behaviour is made: it may load its data
    const bool check_only = vm.count("check") > 0;
    if (check_only && robot::python_module(def.behaviour) && !std::filesystem::is_directory(def.behaviour.python_dir))
      throw po::error("--python-dir " + def.behaviour.python_dir + " is not a directory");
    // From here on a stop signal must reach Python: a module may hang at import.
    handle_stop_signals(def.id.team, def.id.player);
    if (robot::python_module(def.behaviour)) {
      // Python's own signal handlers stay off: SIGINT/SIGTERM stop the shim (handle_stop_signals); no
      // program directory on sys.path: the behaviour's modules come from --python-dir alone.
      interpreter.emplace(/*init_signal_handlers=*/false, 0, nullptr, /*add_program_dir_to_path=*/false);
    }
    behaviour = apps::make_robot_behaviour(
        robot_options, "robot_shim " + std::to_string(def.id.team) + "/" + std::to_string(def.id.player));
    if (check_only) return 0;
  } catch (const po::error& e) {
    log->error("{} (see --help)", e.what());
    return kUsageError;
  } catch (const ConfigError& e) {
    log->error("{}", e.what());
    return kUsageError;
  } catch (const behaviour::BehaviourError& e) {
    log->error("{}", e.what());
    return kUsageError;
  } catch (const python::PythonBehaviourError& e) {
    if (g_stop_signal) return stop_status(); // stopped while the module was imported
    log->error("{}", e.what());
    return kUsageError;
  } catch (const std::invalid_argument& e) { // the match secret
    log->error("{}", e.what());
    return kUsageError;
  }

  // From here on its lines name the robot, as its behaviour's lines do.
  const std::shared_ptr<spdlog::logger> robot_log =
      apps::program_log("robot_shim " + std::to_string(def.id.team) + "/" + std::to_string(def.id.player));
  robot_log->set_level(log->level());
  try {
    robot::Robot robot(std::move(def), std::move(behaviour));
    if (g_stop_signal) return stop_status(); // before run_robot, which starts afresh
    switch (transport::run_robot(robot, node, *robot_log)) {
      case transport::RobotExit::kMatchOver: return 0;
      case transport::RobotExit::kRejected: return kUsageError;
      case transport::RobotExit::kNoWorld: return 1;
      case transport::RobotExit::kInterrupted: return stop_status();
    }
  } catch (const std::exception& e) {
    robot_log->error("{}", e.what());
  }
  return 1;
}
