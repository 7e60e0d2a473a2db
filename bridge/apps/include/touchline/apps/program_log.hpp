#pragma once
// A program's log (sim_world, robot_shim, touchline_match): spdlog, each message one line on
// stderr as "NAME: message", the form every error line of the programs has always had, so
// tools and tests that read them read the same lines; --log-level chooses which appear.
#include <memory>
#include <string>

#include <boost/program_options/options_description.hpp>
#include <spdlog/logger.h>

namespace touchline::apps {

/// The levels --log-level takes, lowest first, for --help and errors.
inline constexpr const char* kLogLevels = "trace, debug, info, warning, error, off";

/// A logger named `name` that writes "name: message" lines to stderr at level info.
std::shared_ptr<spdlog::logger> program_log(const std::string& name);

/// Adds --log-level (default info) to `options`, stored in `level`.
void add_log_level_option(boost::program_options::options_description& options, std::string& level);

/// Sets `log`'s level from its name (kLogLevels; "warn" and "err" too). Throws
/// boost::program_options::error (a usage error, as any bad option) naming the levels for any other.
void set_log_level(spdlog::logger& log, const std::string& level);

} // namespace touchline::apps
