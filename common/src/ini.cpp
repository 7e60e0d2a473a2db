#include "touchline/ini.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include <sys/stat.h>

namespace po = boost::program_options;

namespace touchline {

namespace {
void store_stream(const po::options_description& options, std::istream& in, const std::string& origin,
                  bool ignore_unknown = false) {
  try {
    po::variables_map vm;
    po::store(po::parse_config_file(in, options, ignore_unknown), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    throw ConfigError(origin + ": " + e.what());
  }
}
} // namespace

void IniSchema::read_file(const std::string& path, bool ignore_unknown) const {
  // A directory opens as a stream that reads nothing: without this, a wrong path read as
  // an empty file and every key silently kept its default.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw ConfigError(path + ": cannot open config file (it is a directory)");
  errno = 0;
  std::ifstream in(path);
  if (!in)
    throw ConfigError(path + ": cannot open config file (" +
                      (errno ? std::strerror(errno) : std::string("unreadable")) + ")");
  store_stream(options_, in, path, ignore_unknown);
  if (in.bad()) throw ConfigError(path + ": cannot read config file");
}

void IniSchema::apply_override(const std::string& assignment) const {
  const auto eq = assignment.find('=');
  const auto dot = assignment.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq)
    throw ConfigError("override '" + assignment + "': expected section.key=value");
  std::istringstream in("[" + assignment.substr(0, dot) + "]\n" + assignment.substr(dot + 1) + "\n");
  store_stream(options_, in, "override '" + assignment + "'");
}

} // namespace touchline
