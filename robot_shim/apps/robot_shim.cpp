// robot_shim: one robot's own code (Blackboard, adapters, MotionAdapter, WalkCycle and a
// behaviour) playing in sim_world over LCM. Thin program: options -> Robot -> run_robot.
#include <csignal>
#include <iostream>
#include <sstream>

#include <boost/program_options.hpp>

#include "touchline/behaviour/registry.hpp"
#include "touchline/ini.hpp"
#include "touchline/lcm/robot_node.hpp"

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
  return out.str();
}

} // namespace

int main(int argc, char** argv) {
  int team = -1, player = -1;
  std::string behaviour_name = "stand", walk_config;
  std::vector<std::string> param_args;
  transport::RobotNodeDef node;

  po::options_description options(
      "robot_shim: runs one robot's code in a sim_world match over LCM.\n"
      "Usage: robot_shim --team T --player N [options]\nOptions");
  options.add_options()
    ("help,h", "print this help and exit")
    ("team", po::value(&team)->required(), "team index, 0 or 1")
    ("player", po::value(&player)->required(), "player number, 1..7 (and within the world's team size)")
    ("behaviour", po::value(&behaviour_name)->default_value(behaviour_name), "the C++ behaviour to run (see the list below)")
    ("param", po::value(&param_args)->composing(), "a behaviour parameter, key=value (repeatable)")
    ("walk-config", po::value(&walk_config), "walk parameters file ([walk] section); default: the built-in walk")
    ("lcm-url", po::value(&node.lcm_url)->default_value(node.lcm_url), "LCM provider URL")
    ("join-timeout", po::value(&node.join_timeout_s)->default_value(node.join_timeout_s), "wall seconds to wait for sim_world to accept us")
    ("world-timeout", po::value(&node.world_timeout_s)->default_value(node.world_timeout_s), "wall seconds of silence from sim_world before exiting");

  std::unique_ptr<api::Behaviour> behaviour;
  robot::WalkDef walk;
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n" << behaviour_list();
      return 0;
    }
    po::notify(vm);
    if (team != 0 && team != 1) throw po::error("--team must be 0 or 1 (got " + std::to_string(team) + ")");
    if (player < 1 || player > kMaxTeamSize)
      throw po::error("--player must be 1.." + std::to_string(kMaxTeamSize) + " (got " + std::to_string(player) + ")");
    if (node.join_timeout_s <= 0 || node.world_timeout_s <= 0) throw po::error("timeouts must be > 0");
    if (!walk_config.empty()) walk = robot::load_walk_def(walk_config);
    behaviour = behaviour::make_behaviour(behaviour_name, parse_params(param_args));
  } catch (const po::error& e) {
    std::cerr << "robot_shim: " << e.what() << " (see --help)\n";
    return kUsageError;
  } catch (const ConfigError& e) {
    std::cerr << "robot_shim: " << e.what() << "\n";
    return kUsageError;
  } catch (const behaviour::BehaviourError& e) {
    std::cerr << "robot_shim: " << e.what() << "\n";
    return kUsageError;
  }

  std::signal(SIGINT, [](int) { transport::request_robot_stop(); });
  std::signal(SIGTERM, [](int) { transport::request_robot_stop(); });
  try {
    robot::Robot robot({team, player}, walk, std::move(behaviour));
    switch (transport::run_robot(robot, node, std::cerr)) {
      case transport::RobotExit::kMatchOver: return 0;
      case transport::RobotExit::kRejected: return kUsageError;
      case transport::RobotExit::kNoWorld: return 1;
      case transport::RobotExit::kInterrupted: return 130;
    }
  } catch (const std::exception& e) {
    std::cerr << "robot_shim: " << e.what() << "\n";
  }
  return 1;
}
