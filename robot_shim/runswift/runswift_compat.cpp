// The symbols rUNSWift's walk files expect from parts of their tree we do not build (their
// defining files drag in threads, vision and the filesystem): their Logger (here every log
// line is discarded) and the offNao flag. And their options: their own populate_options
// gives every default, one of their option files may override them.
#include "runswift_compat.hpp"

#include <fstream>
#include <ostream>
#include <streambuf>

#include <boost/program_options.hpp>

#include "touchline/ini.hpp"
#include "utils/Logger.hpp"
#include "utils/options.hpp"

/// Their walk runs as on the robot (the flag switches camera-pose shortcuts only).
bool offNao = false;

namespace {
/// Swallows what their code logs: the match's output is ours.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};
NullBuffer null_buffer;
std::ostream null_stream(&null_buffer);
} // namespace

Logger::Logger(const char*) : logStream(&null_stream) {}
Logger::~Logger() = default;
Logger* Logger::instance() {
  static Logger logger("touchline");
  return &logger;
}
std::ostream& Logger::realLlog(int) { return null_stream; }
std::ostream& Logger::realLlog(int, int) { return null_stream; }

namespace touchline::robot::runswift {

namespace po = boost::program_options;

po::variables_map options(const std::string& config_file) {
  po::options_description description;
  populate_options(description);
  po::variables_map vm;
  if (!config_file.empty()) {
    std::ifstream in(config_file);
    if (!in) throw ConfigError(config_file + ": cannot open the rUNSWift option file");
    try {
      po::store(po::parse_config_file(in, description, /*allow_unregistered=*/true), vm);
    } catch (const po::error& e) {
      throw ConfigError(config_file + ": " + e.what());
    }
  }
  po::store(po::parsed_options(&description), vm); // the defaults of what the file left out
  po::notify(vm);
  return vm;
}

} // namespace touchline::robot::runswift
