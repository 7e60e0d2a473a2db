// sim_world: plays a match in the Box2D world with robot_shim processes over LCM.
// Thin program: options -> WorldConfig + WorldNodeDef -> run_world -> summary.
#include <csignal>
#include <fstream>
#include <iomanip>
#include <iostream>

#include <boost/program_options.hpp>

#include "touchline/lcm/world_node.hpp"
#include "touchline/sim/config.hpp"

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

void write_summary_json(const std::string& path, const sim::Match& match, const transport::RunSummary& s,
                        uint64_t seed) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write summary to " + path);
  const sim::TruthFrame truth = match.truth();
  out << std::setprecision(9) << "{\n"
      << "  \"seed\": " << seed << ",\n"
      << "  \"frames\": " << s.frames << ",\n"
      << "  \"sim_s\": " << s.sim_s << ",\n"
      << "  \"wall_s\": " << s.wall_s << ",\n"
      << "  \"rtf\": " << (s.wall_s > 0 ? s.sim_s / s.wall_s : 0) << ",\n"
      << "  \"truth_hash\": \"" << transport::hex_hash(s.truth_hash) << "\",\n"
      << "  \"malformed\": " << s.malformed << ",\n"
      << "  \"stale\": " << s.stale << ",\n"
      << "  \"interrupted\": " << (s.interrupted ? "true" : "false") << ",\n"
      << "  \"score\": [" << match.game().score[0] << ", " << match.game().score[1] << "],\n"
      << "  \"ball\": {\"x_mm\": " << truth.ball.x_mm << ", \"y_mm\": " << truth.ball.y_mm << "},\n"
      << "  \"robots\": [";
  for (size_t i = 0; i < truth.robots.size(); ++i) {
    const auto& r = truth.robots[i];
    const sim::Member* m = match.roster().find(r.truth.id);
    out << (i ? ",\n" : "\n") << "    {\"team\": " << r.truth.id.team << ", \"player\": " << r.truth.id.player
        << ", \"active\": " << (r.active ? "true" : "false")
        << ", \"frames_answered\": " << (m ? m->frames_answered : 0)
        << ", \"frames_missed\": " << (m ? m->frames_missed : 0)
        << ", \"behaviour_cpu_us_mean\": " << (m ? m->behaviour_cpu_us_mean() : 0)
        << ", \"behaviour_cpu_us_max\": " << (m ? m->behaviour_cpu_us_max : 0)
        << ", \"localisation_rms_mm\": " << (m ? m->localisation_rms_mm() : 0)
        << ", \"localisation_rms_rad\": " << (m ? m->localisation_rms_rad() : 0)
        << ", \"penalised\": " << (r.penalised ? "true" : "false") << ", \"x_mm\": " << r.truth.body.x_mm
        << ", \"y_mm\": " << r.truth.body.y_mm << ", \"theta_rad\": " << r.truth.body.theta_rad << "}";
  }
  out << "\n  ]\n}\n";
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
  if (s.malformed || s.stale)
    std::cout << "  malformed messages ignored: " << s.malformed << ", late answers dropped: " << s.stale << "\n";
}

} // namespace

int main(int argc, char** argv) {
  std::string config_path, mode = "lockstep";
  std::vector<std::string> overrides;
  transport::WorldNodeDef node;
  uint64_t seed = 1;
  double duration_s = -1;
  int robots = -1;
  std::string gamecontroller;

  po::options_description options(
      "sim_world: plays a match in the Box2D world with robot_shim processes over LCM.\n"
      "Usage: sim_world [options]\nOptions");
  options.add_options()
    ("help,h", "print this help and exit")
    ("config", po::value(&config_path), "world config file ([field], [physics], [match]); default: the built-in SPL 2011 values")
    ("set", po::value(&overrides)->composing(), "override one config value, section.key=value (repeatable)")
    ("robots", po::value(&robots), "robots to wait for before kick-off (default: both full teams)")
    ("duration", po::value(&duration_s), "simulated seconds to play (default: match.duration_s)")
    ("mode", po::value(&mode)->default_value(mode), "lockstep (wait for every robot, as fast as possible), realtime (lockstep paced to --speed x wall clock) or free (never wait, paced; late answers apply late)")
    ("speed", po::value(&node.speed)->default_value(node.speed), "real-time multiple for realtime and free modes")
    ("robot-timeout-ms", po::value(&node.robot_timeout_ms)->default_value(node.robot_timeout_ms), "wall time a robot may take to answer a frame before it is marked inactive")
    ("join-timeout", po::value(&node.join_timeout_s)->default_value(node.join_timeout_s), "wall seconds to wait for the robots to join")
    ("seed", po::value(&seed)->default_value(seed), "random seed: the camera noise, false negatives and falls all draw from it")
    ("lcm-url", po::value(&node.lcm_url)->default_value(node.lcm_url), "LCM provider URL")
    ("summary", po::value(&node.summary_path), "write a JSON summary of the match to this path")
    ("gamecontroller", po::value(&gamecontroller),
     "take the game from the official SPL GameController's UDP packets (versions 15 and 18) on [ADDRESS:]PORT, e.g. 127.0.0.1:3838, instead of the built-in referee")
    ("log", po::value(&node.log_path), "record every message of the match to this LCM event log (lcm-logger format; timestamps are simulated time)")
    ("quiet", "no progress lines");

  sim::WorldConfig config;
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n";
      return 0;
    }
    po::notify(vm);
    node.pacing = parse_mode(mode);
    if (node.speed <= 0) throw po::error("--speed must be > 0");
    if (node.robot_timeout_ms <= 0) throw po::error("--robot-timeout-ms must be > 0");
    node.progress = !vm.count("quiet");
    if (duration_s > 0) overrides.push_back("match.duration_s=" + std::to_string(duration_s));
    else if (vm.count("duration")) throw po::error("--duration must be > 0");
    if (!gamecontroller.empty()) {
      node.gamecontroller = parse_gamecontroller(gamecontroller);
      overrides.push_back("rules.referee=false"); // the GameController referees instead
    }
    config = sim::load_world_config(config_path, overrides);
    node.robots = robots >= 0 ? robots : 2 * config.match.team_size;
    if (node.robots < 1 || node.robots > 2 * config.match.team_size)
      throw po::error("--robots must be 1.." + std::to_string(2 * config.match.team_size));
  } catch (const po::error& e) {
    std::cerr << "sim_world: " << e.what() << " (see --help)\n";
    return kUsageError;
  } catch (const ConfigError& e) {
    std::cerr << "sim_world: " << e.what() << "\n";
    return kUsageError;
  }

  std::signal(SIGINT, [](int) { transport::request_stop(); });
  std::signal(SIGTERM, [](int) { transport::request_stop(); });
  try {
    sim::Match match(config, seed);
    const transport::RunSummary summary = transport::run_world(match, node, std::cerr);
    print_summary(match, summary);
    if (!node.summary_path.empty()) write_summary_json(node.summary_path, match, summary, seed);
    return summary.interrupted ? 130 : 0;
  } catch (const std::exception& e) {
    std::cerr << "sim_world: " << e.what() << "\n";
    return 1;
  }
}
