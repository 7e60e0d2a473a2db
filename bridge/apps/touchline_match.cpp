// touchline_match: a whole refereed match in one process, the world and every robot (C++
// and Python behaviours alike, one interpreter for all), no transport. The world takes
// sim_world's options, each robot robot_shim's, so a robot is the same robot in both
// modes; the truth hash and the summary are the lockstep run's (same seed, same hash).
// Thin program: options -> InProcessMatch -> summary.
#include <chrono>
#include <csignal>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>

#include <boost/program_options.hpp>
#include <pybind11/embed.h>

#include "touchline/apps/program_log.hpp"
#include "touchline/apps/robot_options.hpp"
#include "touchline/apps/summary_json.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/cli.hpp"
#include "touchline/ini.hpp"
#include "touchline/inprocess/inprocess_match.hpp"
#include "touchline/lcm/codec.hpp"
#include "touchline/lcm/match_config.hpp"
#include "touchline/lcm/match_recorder.hpp"
#include "touchline/lcm/world_messages.hpp"
#include "touchline/python/python_behaviour.hpp"
#include "touchline/python/tick_guard.hpp"
#include "touchline/robot_api/data.hpp"
#include "touchline/sim/config.hpp"
#include "touchline/version.hpp"

namespace po = boost::program_options;
using namespace touchline;

namespace {

constexpr int kUsageError = 2;
constexpr const char* kUsage =
    "touchline_match: plays a whole match with the world and every robot in one process.\n"
    "Usage: touchline_match [world options] -- [robot options] -- [robot options] ...\n"
    "The world options are sim_world's (below); each group after a -- is one robot, in robot_shim's\n"
    "options (robot_shim --help), e.g. --team 0 --player 1 --behaviour py --param skill=Team.\n"
    "A robot's bus options (--lcm-url, --secret-file, --join-timeout, --world-timeout,\n"
    "--snapshot-every) are accepted and unused; every robot needs the same --data-dir. Same seed and\n"
    "robots: the same match, truth hash included, as sim_world + robot_shim in lockstep.\n"
    "Exit status: 0 played, 2 bad options (one line), 1 failed, 128 + signal when stopped.\nWorld options";

volatile std::sig_atomic_t g_stop_signal = 0;

void on_stop_signal(int signal) {
  if (g_stop_signal != 0) std::_Exit(128 + g_stop_signal); // a second signal: at once
  g_stop_signal = signal;
  python::request_stop(); // running Python is interrupted; the loop ends after this frame
}

/// argv split at each "--": the world's options, then one group per robot.
std::vector<std::vector<std::string>> groups(int argc, char** argv) {
  std::vector<std::vector<std::string>> out(1);
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--") out.emplace_back();
    else out.back().emplace_back(argv[i]);
  }
  return out;
}

/// One robot's group, read as robot_shim reads its command line.
apps::RobotOptions parse_robot(const std::vector<std::string>& args) {
  apps::RobotOptions robot;
  po::options_description options;
  apps::add_robot_options(options, robot);
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(options).run(), vm);
  po::notify(vm);
  apps::finish_robot_options(robot);
  return robot;
}

/// CPU seconds this process has used: what the match costs whatever else the machine runs.
double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

void log_progress(spdlog::logger& log, const sim::Match& match, double wall_s) {
  const double sim_s = static_cast<double>(match.utime()) * 1e-6;
  log.info("{:.0f} s simulated, x{:.1f} real time", sim_s, sim_s / std::max(wall_s, 1e-9));
}

} // namespace

int main(int argc, char** argv) {
  std::string config_path, summary_path, log_path;
  std::vector<std::string> overrides;
  uint64_t seed = 1;
  double duration_s = -1;
  po::options_description options(kUsage);
  options.add_options()
    ("help,h", "print this help and exit")
    ("version", kVersionHelp)
    ("config", po::value(&config_path), "world config file ([field], [physics], [match]); default: the built-in SPL 2011 values")
    ("set", po::value(&overrides)->composing(), "override one config value, section.key=value (repeatable)")
    ("duration", number_option("--duration", &duration_s, 0.001, 1e9, /*show_default=*/false),
     "simulated seconds to play, up to 1e9 (default: match.duration_s)")
    ("seed", number_option("--seed", &seed, uint64_t{0}, std::numeric_limits<uint64_t>::max()),
     "random seed, 0..2^64-1: the camera noise, false negatives and falls all draw from it")
    ("summary", po::value(&summary_path),
     "write a JSON summary of the match to this path at its end, as sim_world --summary does (the "
     "match's events, goals, penalties, falls and set plays, as \"match_events\"), with the world's own wall time "
     "(world_wall_s, physics_rtf) and the match's CPU time (cpu_s, cpu_rtf) (checked writable at start)")
    ("log", po::value(&log_path),
     "record the match to this LCM event log as sim_world --log does: TL_MATCH, TL_GAME, TL_TRUTH every "
     "frame, TL_EVENT and each robot's TL_ACT_<team>_<player> every frame (no TL_SENSE; timestamps are "
     "simulated time; checked writable at start)")
    ("print-match", "print the match's plan as sim_world --check does (planned length, goal stoppage, duration, "
     "team size, field size: the config after every --set) as one JSON line and exit, without robots")
    ("quiet", "no progress lines");

  std::string log_level;
  apps::add_log_level_option(options, log_level);
  const std::shared_ptr<spdlog::logger> log = apps::program_log("touchline_match");

  const auto args = groups(argc, argv);
  sim::WorldConfig config;
  std::vector<apps::RobotOptions> robots;
  bool quiet = false;
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(args[0]).options(options).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n" << apps::behaviour_list();
      return 0;
    }
    if (version_requested(vm, "touchline_match")) return 0;
    po::notify(vm);
    quiet = vm.count("quiet") > 0;
    apps::set_log_level(*log, log_level);
    if (vm.count("duration")) overrides.push_back("match.duration_s=" + format_number(duration_s));
    config = sim::load_world_config(config_path, overrides);
    if (vm.count("print-match")) {
      std::cout << apps::match_plan_json(config) << "\n";
      return 0;
    }
    if (args.size() < 2) throw po::error("no robots: give each one's options after a --");
    if (!summary_path.empty()) require_writable("--summary", summary_path);
    if (!log_path.empty()) require_writable("--log", log_path);
    for (size_t i = 1; i < args.size(); ++i) {
      try {
        robots.push_back(parse_robot(args[i]));
      } catch (const std::exception& e) {
        throw po::error("robot " + std::to_string(i) + ": " + e.what());
      }
      // api::data_dir is the process's: one for every robot here.
      if (robots.back().data_dir != robots.front().data_dir)
        throw po::error("robot " + std::to_string(i) + ": --data-dir " + robots.back().data_dir +
                        " differs from robot 1's (" + robots.front().data_dir + "); one process has one");
    }
  } catch (const po::error& e) {
    log->error("{} (see --help)", e.what());
    return kUsageError;
  } catch (const ConfigError& e) {
    log->error("{}", e.what());
    return kUsageError;
  }

  struct sigaction action {};
  sigemptyset(&action.sa_mask);
  action.sa_handler = on_stop_signal;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  // One interpreter for every Python robot (each keeps its own modules); it outlives them.
  std::optional<pybind11::scoped_interpreter> interpreter;
  std::optional<inprocess::InProcessMatch> play;
  try {
    api::set_data_dir(robots.front().data_dir); // before the behaviours are made: they may load their data
    play.emplace(config, seed);
    for (size_t i = 0; i < robots.size(); ++i) {
      const apps::RobotOptions& robot = robots[i];
      const RobotId id = robot.def.id;
      if (robot::python_module(robot.def.behaviour) && !interpreter)
        interpreter.emplace(/*init_signal_handlers=*/false, 0, nullptr, /*add_program_dir_to_path=*/false);
      try {
        play->add_robot(robot.def, apps::make_robot_behaviour(robot, "touchline_match " + std::to_string(id.team) +
                                                                         "/" + std::to_string(id.player)));
      } catch (const std::invalid_argument& e) { // the roster refused it
        throw ConfigError("robot " + std::to_string(i + 1) + " (" + sim::describe(id) + "): " + e.what());
      }
    }
  } catch (const python::PythonBehaviourError& e) {
    if (g_stop_signal) return 128 + g_stop_signal; // stopped while a module was imported
    log->error("{}", e.what());
    return kUsageError;
  } catch (const std::exception& e) { // ConfigError, behaviour::BehaviourError
    log->error("{}", e.what());
    return kUsageError;
  }

  try {
    sim::Match& match = play->match();
    std::vector<sim::MatchEvent> events;
    transport::TruthHash truth_hash;
    std::optional<transport::MatchRecorder> recorder;
    if (!log_path.empty()) recorder.emplace(log_path);
    const auto record_bytes = [&](const std::string& channel, const std::vector<uint8_t>& bytes,
                                  std::optional<int64_t> utime = std::nullopt) {
      recorder->record(channel, bytes.data(), static_cast<int>(bytes.size()), utime.value_or(match.utime()));
      if (!recorder->error().empty()) throw std::runtime_error(recorder->error()); // no log with a hole
    };
    // Messages are encoded only when there is a log to write them to.
    const auto record = [&](const char* channel, const auto& msg) {
      if (recorder) record_bytes(channel, transport::encoded(msg));
    };
    play->start();
    record(transport::kMatchChannel, transport::to_lcm(config, seed, match.utime()));
    record(transport::kGameChannel, transport::to_msg(match.game(), match.utime()));
    const auto start = std::chrono::steady_clock::now();
    const double start_cpu_s = process_cpu_s();
    const auto wall_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    // As the world node runs its lockstep frames: every robot answers, the world steps, and
    // the truth after the step goes into the hash.
    while (!match.finished() && !g_stop_signal) {
      const int64_t sense_utime = match.utime();
      play->step_frame();
      // Each robot's answer, as sim_world logs a robot_shim's act: at its frame's time, before
      // the truth it led to (the viewer shows roles and beliefs from them). No process here, so
      // no shim instance: 0.
      if (recorder)
        for (const RobotAct& act : play->acts())
          record_bytes(transport::act_channel(act.id), transport::encoded(transport::to_lcm(act, sense_utime, 0)),
                       sense_utime);
      const std::vector<uint8_t> truth = transport::encoded(transport::to_msg(match.truth()));
      truth_hash.add(truth.data(), truth.size());
      if (recorder) record_bytes(transport::kTruthChannel, truth);
      std::vector<sim::MatchEvent> new_events = match.take_events();
      for (const sim::MatchEvent& event : new_events) record(transport::kEventChannel, transport::to_msg(event));
      // The game as the world node says it: at once when it changed, else once a second.
      if (!new_events.empty() || match.frame() % kFramesPerSecond == 0)
        record(transport::kGameChannel, transport::to_msg(match.game(), match.utime()));
      for (sim::MatchEvent& event : new_events) events.push_back(std::move(event));
      if (!quiet && match.frame() % (10 * kFramesPerSecond) == 0) log_progress(*log, match, wall_s());
    }
    for (sim::MatchEvent& event : match.take_events()) {
      record(transport::kEventChannel, transport::to_msg(event));
      events.push_back(std::move(event));
    }
    record(transport::kGameChannel, transport::to_msg(match.game(), match.utime(), true));
    transport::RunSummary summary;
    summary.frames = match.frame();
    summary.sim_s = static_cast<double>(match.utime()) * 1e-6;
    summary.wall_s = wall_s();
    summary.truth_hash = truth_hash.value();
    summary.interrupted = g_stop_signal != 0;
    summary.events = std::move(events);
    std::cout << std::fixed << std::setprecision(1) << "touchline_match: " << summary.frames << " frames, "
              << summary.sim_s << " s simulated in " << summary.wall_s << " s (x"
              << (summary.wall_s > 0 ? summary.sim_s / summary.wall_s : 0) << " real time), score "
              << match.game().score[0] << ":" << match.game().score[1] << ", truth hash "
              << transport::hex_hash(summary.truth_hash) << "\n";
    if (!summary_path.empty())
      apps::write_summary_json(summary_path, match, summary, seed,
                               apps::InProcessExtras{play->world_wall_s(), process_cpu_s() - start_cpu_s});
    return summary.interrupted ? 128 + g_stop_signal : 0;
  } catch (const std::exception& e) {
    log->error("{}", e.what());
    return 1;
  }
}
