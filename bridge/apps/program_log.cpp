#include "touchline/apps/program_log.hpp"

#include <boost/program_options/errors.hpp>
#include <boost/program_options/value_semantic.hpp>
#include <spdlog/sinks/stdout_sinks.h>

namespace touchline::apps {

std::shared_ptr<spdlog::logger> program_log(const std::string& name) {
  // Unregistered and unsynchronised apart from the sink's own lock: each program makes one.
  auto log = std::make_shared<spdlog::logger>(name, std::make_shared<spdlog::sinks::stderr_sink_mt>());
  log->set_pattern("%n: %v");
  log->set_level(spdlog::level::info);
  log->flush_on(spdlog::level::trace); // a line is seen when it is said, as a crash must not eat it
  return log;
}

void add_log_level_option(boost::program_options::options_description& options, std::string& level) {
  options.add_options()("log-level", boost::program_options::value(&level)->default_value("info"),
                        (std::string("which lines this program prints: ") + kLogLevels +
                         " (warning: only what went wrong)").c_str());
}

void set_log_level(spdlog::logger& log, const std::string& level) {
  const spdlog::level::level_enum parsed = spdlog::level::from_str(level);
  // from_str answers "off" for any name it does not know: only "off" itself may mean it.
  if (parsed == spdlog::level::off && level != "off")
    throw boost::program_options::error("--log-level " + level + ": not a level (" + kLogLevels + ")");
  log.set_level(parsed);
}

} // namespace touchline::apps
