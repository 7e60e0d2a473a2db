#include "touchline/ini.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include <sys/stat.h>

namespace po = boost::program_options;

namespace touchline {

namespace {
/// What would be right instead of an unknown "section.key": " (the keys of [section]: a, b)",
/// or " (the sections: field, physics)" when the section is unknown too.
std::string known_keys(const po::options_description& options, const std::string& unknown) {
  const std::string section = unknown.substr(0, unknown.find('.'));
  std::vector<std::string> keys, sections;
  for (const auto& option : options.options()) {
    const std::string& name = option->long_name();
    const std::string of = name.substr(0, name.find('.'));
    if (of == section) keys.push_back(name.substr(of.size() + 1));
    if (std::find(sections.begin(), sections.end(), of) == sections.end()) sections.push_back(of);
  }
  const auto join = [](const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
  };
  return keys.empty() ? " (the sections: " + join(sections) + ")"
                      : " (the keys of [" + section + "]: " + join(keys) + ")";
}

void store_stream(const po::options_description& options, std::istream& in, const std::string& origin,
                  bool ignore_unknown = false) {
  try {
    po::variables_map vm;
    po::store(po::parse_config_file(in, options, ignore_unknown), vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    throw ConfigError(origin + ": " + e.what() + known_keys(options, e.get_option_name()));
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
