// sim_world: plays a match in the Box2D world with robot_shim processes over LCM.
// Thin program: options -> WorldConfig + WorldNodeDef -> run_world -> summary.
#include <algorithm>
#include <csignal>
#include <iomanip>
#include <iostream>
#include <limits>

#include <boost/program_options.hpp>

#include "touchline/apps/program_log.hpp"
#include "touchline/apps/summary_json.hpp"
#include "touchline/cli.hpp"
#include "touchline/lcm/lcm_url.hpp"
#include "touchline/lcm/world_node.hpp"
#include "touchline/sim/config.hpp"
#include "touchline/version.hpp"

namespace po = boost::program_options;
using namespace touchline;

namespace {

constexpr int kUsageError = 2;

transport::Pacing parse_mode(const std::string& mode) {
  if (mode == "lockstep") return transport::Pacing::kLockstep;
  if (mode == "realtime") return transport::Pacing::kRealtime;
  if (mode == "free") return transport::Pacing::kFree;
  throw po::error("--mode must be lockstep, realtime or free (got '" + mode + "')");
}

transport::GameControllerReceiverOptions parse_gamecontroller(const std::string& text) {
  transport::GameControllerReceiverOptions options;
  const auto colon = text.rfind(':');
  const std::string port = colon == std::string::npos ? text : text.substr(colon + 1);
  if (colon != std::string::npos) options.address = text.substr(0, colon);
  char* end = nullptr;
  const long value = std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || value < 1 || value > 65535)
    throw po::error("--gamecontroller must be [ADDRESS:]PORT with a port 1..65535 (got '" + text + "')");
  options.port = static_cast<uint16_t>(value);
  return options;
}

void print_summary(const sim::Match& match, const transport::RunSummary& s) {
  std::cout << std::fixed << std::setprecision(1) << "sim_world: " << s.frames << " frames, " << s.sim_s
            << " s simulated in " << s.wall_s << " s (x" << (s.wall_s > 0 ? s.sim_s / s.wall_s : 0)
            << " real time), truth hash " << transport::hex_hash(s.truth_hash) << "\n";
  for (const auto& r : match.truth().robots) {
    const sim::Member* m = match.roster().find(r.truth.id);
    std::cout << "  " << sim::describe(r.truth.id) << ": at (" << std::setprecision(0) << r.truth.body.x_mm
              << ", " << r.truth.body.y_mm << ") mm heading " << std::setprecision(2) << r.truth.body.theta_rad
              << " rad, " << (r.active ? "active" : "INACTIVE") << ", answered " << m->frames_answered
              << ", missed " << m->frames_missed << "\n";
  }
  if (s.malformed || s.stale || s.future || s.unauthenticated || s.handler_failures)
    std::cout << "  messages dropped: malformed " << s.malformed << " (implausible " << s.implausible << ", future "
              << s.future << "), late " << s.stale << ", unauthenticated " << s.unauthenticated
              << ", failed " << s.handler_failures << "\n";
  if (s.resent_senses) std::cout << "  senses sent again to late robots: " << s.resent_senses << "\n";
  if (s.slow_answers)
    std::cout << "  answers waited for past --robot-timeout-ms (their shim still ran): " << s.slow_answers << "\n";
}

} // namespace

int main(int argc, char** argv) {
  std::string config_path, mode = "lockstep";
  std::vector<std::string> overrides;
  transport::WorldNodeDef node;
  uint64_t seed = 1;
  double duration_s = -1;
  int robots = -1;
  std::string gamecontroller, secret_file;

  po::options_description options(
      "sim_world: plays a match in the Box2D world with robot_shim processes over LCM.\n"
      "Usage: sim_world [options]\nOptions");
  options.add_options()
    ("help,h", "print this help and exit")
    ("version", kVersionHelp)
    ("config", po::value(&config_path), "world config file ([field], [physics], [match]); default: the built-in SPL 2011 values")
    ("set", po::value(&overrides)->composing(), "override one config value, section.key=value (repeatable)")
    ("robots", number_option("--robots", &robots, 1, 2 * kMaxTeamSize, /*show_default=*/false),
     "robots to wait for before kick-off (default: both full teams)")
    ("duration", number_option("--duration", &duration_s, 0.001, 1e9, /*show_default=*/false),
     "simulated seconds to play, up to 1e9 (default: match.duration_s)")
    ("mode", po::value(&mode)->default_value(mode), "lockstep (wait for every robot, as fast as possible), realtime (lockstep paced to --speed x wall clock) or free (never wait, paced; late answers apply late)")
    ("speed", number_option("--speed", &node.speed, 0.01, 1000.0), "real-time multiple for realtime and free modes, 0.01..1000")
    ("robot-timeout-ms", number_option("--robot-timeout-ms", &node.robot_timeout_ms, int64_t{1}, int64_t{3600000}),
     "wall time a robot may take to answer a frame before it is marked inactive, 1..3600000 ms; lockstep and "
     "realtime: unless its robot_shim still runs on this machine (--live-robot-timeout-ms)")
    ("live-robot-timeout-ms",
     number_option("--live-robot-timeout-ms", &node.live_robot_timeout_ms, int64_t{1}, int64_t{86400000}),
     "lockstep and realtime: wall time a robot whose robot_shim still runs on this machine (a busy machine, a "
     "debugger's breakpoint) may take to answer a frame, so that load does not change the match, 1..86400000 ms")
    ("join-timeout", number_option("--join-timeout", &node.join_timeout_s, 0.01, 86400.0),
     "wall seconds to wait for the robots to join, 0.01..86400")
    ("seed", number_option("--seed", &seed, uint64_t{0}, std::numeric_limits<uint64_t>::max()),
     "random seed, 0..2^64-1: the camera noise, false negatives and falls all draw from it")
    ("lcm-url", po::value(&node.lcm_url)->default_value(node.lcm_url),
     "LCM provider URL (opened once at start: a URL LCM cannot open is a usage error)")
    ("secret-file", po::value(&secret_file),
     "the match secret (hex) every message is authenticated with; default: $TOUCHLINE_MATCH_SECRET. "
     "Every program of the match needs the same one")
    ("resend-ms", number_option("--resend-ms", &node.resend_ms, int64_t{1}, int64_t{3600000}),
     "wall milliseconds after which a frame's sense goes out again to robots that have not answered, 1..3600000")
    ("summary", po::value(&node.summary_path),
     "write a JSON summary of the match to this path at its end (checked writable at start; an existing file is "
     "left alone until then)")
    ("gamecontroller", po::value(&gamecontroller),
     "take the game from the official SPL GameController's UDP packets (versions 15 and 18) on [ADDRESS:]PORT, e.g. 127.0.0.1:3838, instead of the built-in referee")
    ("log", po::value(&node.log_path), "record every message of the match to this LCM event log (lcm-logger format; timestamps are simulated time; checked writable at start)")
    ("quiet", "no progress lines (the match's events and its speed every 10 s)")
    ("check", "check the options and the config (with every --set) as for a match, print the match's planned "
     "length as one JSON line ({\"planned_s\", \"goal_stoppage_s\", \"duration_s\", \"team_size\", \"field_length_mm\", "
     "\"field_width_mm\"}) and exit: "
     "0, or 2 with the one-line error");

  std::string log_level;
  apps::add_log_level_option(options, log_level);
  const std::shared_ptr<spdlog::logger> log = apps::program_log("sim_world");

  sim::WorldConfig config;
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n";
      return 0;
    }
    if (version_requested(vm, "sim_world")) return 0;
    po::notify(vm);
    apps::set_log_level(*log, log_level);
    node.pacing = parse_mode(mode);
    node.key = transport::load_match_key(secret_file);
    node.progress = !vm.count("quiet");
    if (vm.count("duration")) overrides.push_back("match.duration_s=" + format_number(duration_s));
    if (!gamecontroller.empty()) {
      node.gamecontroller = parse_gamecontroller(gamecontroller);
      overrides.push_back("rules.referee=false"); // the GameController referees instead
    }
    config = sim::load_world_config(config_path, overrides);
    node.robots = robots >= 0 ? robots : 2 * config.match.team_size;
    if (node.robots < 1 || node.robots > 2 * config.match.team_size)
      throw po::error("--robots must be 1.." + std::to_string(2 * config.match.team_size));
    // Outputs written at the end: a bad path must not cost a whole match to find out.
    if (!node.summary_path.empty()) require_writable("--summary", node.summary_path);
    if (!node.log_path.empty()) require_writable("--log", node.log_path);
    if (const auto problem = transport::lcm_url_problem(node.lcm_url))
      throw ConfigError("--lcm-url '" + node.lcm_url + "': cannot open LCM: " + *problem);
    if (vm.count("check")) {
      std::cout << apps::match_plan_json(config) << "\n";
      return 0;
    }
  } catch (const po::error& e) {
    log->error("{} (see --help)", e.what());
    return kUsageError;
  } catch (const ConfigError& e) {
    log->error("{}", e.what());
    return kUsageError;
  } catch (const std::invalid_argument& e) { // the match secret
    log->error("{}", e.what());
    return kUsageError;
  }

  std::signal(SIGINT, [](int) { transport::request_stop(); });
  std::signal(SIGTERM, [](int) { transport::request_stop(); });
  try {
    sim::Match match(config, seed);
    const transport::RunSummary summary = transport::run_world(match, node, *log);
    print_summary(match, summary);
    if (!node.summary_path.empty()) apps::write_summary_json(node.summary_path, match, summary, seed);
    return summary.interrupted ? 130 : 0;
  } catch (const std::exception& e) {
    log->error("{}", e.what());
    return 1;
  }
}
