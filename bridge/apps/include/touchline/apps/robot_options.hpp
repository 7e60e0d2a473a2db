#pragma once
// One robot as robot_shim's command line describes it: the options, read into a RobotDef
// (with the files it names loaded) and the behaviour made from it. robot_shim plays the
// robot over LCM; touchline_match plays several in one process from the same command
// lines, so a robot is the same robot in both modes.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "touchline/lcm/robot_node.hpp"
#include "touchline/robot/robot_def.hpp"
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::apps {

/// What the options set; defaults are robot_shim's.
struct RobotOptions {
  RobotOptions();
  robot::RobotDef def;             ///< id, behaviour (name, params, python_dir), engine, localisation
  robot::RobotConfigFiles files;   ///< --walk-config, --kick-config, --head-config, --field-config
  std::vector<std::string> params; ///< --param key=value, as given
  std::string data_dir;            ///< --data-dir: api::data_path looks there
  std::string behaviour_plugin;    ///< --behaviour-plugin: a team's library makes def.behaviour (behaviour_plugin.hpp)
  std::string secret_file;         ///< --secret-file (the bus only)
  transport::RobotNodeDef node;    ///< --lcm-url, timeouts, snapshots (the bus only)
  /// Far above sim_world's 1000 ms robot timeout, so a slow but finishing tick is the world's
  /// to judge; and above what a loaded machine takes to load a large first tick (a 4 MB
  /// learned policy took over 2 s with the sanitizer build beside it). The bound is for code
  /// that hangs.
  int64_t tick_timeout_ms = 10000; ///< --tick-timeout-ms: wall time one Python tick may take
};

/// robot_shim's options, bound to `o`.
void add_robot_options(boost::program_options::options_description& options, RobotOptions& o);

/// The behaviours --behaviour names, for --help.
std::string behaviour_list();

/// After notify: the params parsed, the files read into o.def, the walk engine's name and
/// the data directory checked. Throws po::error (a bad option) or ConfigError (a bad file).
void finish_robot_options(RobotOptions& o);

/// The behaviour o.def names, made for the robot o.def.id (by o.behaviour_plugin when set); a Python one (a running
/// interpreter needed) is logged as `log_name` and bounded by o.tick_timeout_ms. Throws as
/// apps::make_behaviour does.
std::unique_ptr<api::Behaviour> make_robot_behaviour(const RobotOptions& o, const std::string& log_name);

} // namespace touchline::apps
