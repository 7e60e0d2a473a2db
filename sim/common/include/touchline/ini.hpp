#pragma once
// Reads INI files into definition structs: each field is bound to "section.key" with its
// default and a description, unknown keys and bad values are one-line errors.
#include <sstream>
#include <stdexcept>
#include <string>

#include <boost/program_options.hpp>

namespace touchline {

/// A configuration problem, with a message fit for one line on stderr.
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws ConfigError "<key> must be <rule> (got <value>)": what every validate() says.
template <typename T>
[[noreturn]] void config_fail(const char* key, const std::string& rule, T got) {
  std::ostringstream out;
  out << key << " must be " << rule << " (got " << got << ")";
  throw ConfigError(out.str());
}

// Range checks for validate() functions, written as !(ok) so that NaN fails too.
inline void require_positive(const char* key, float value) {
  if (!(value > 0)) config_fail(key, "> 0", value);
}
inline void require_non_negative(const char* key, float value) {
  if (!(value >= 0)) config_fail(key, ">= 0", value);
}
inline void require_fraction(const char* key, float value) {
  if (!(value >= 0 && value <= 1)) config_fail(key, "in [0, 1]", value);
}

class IniSchema {
 public:
  explicit IniSchema(const std::string& caption) : options_(caption) {}

  /// Binds `*field` to `key` ("section.name"). A read sets only the keys its source
  /// names, so files and overrides can be applied one after another.
  template <typename T>
  IniSchema& bind(const char* key, T* field, const char* description) {
    options_.add_options()(key, boost::program_options::value<T>(field), description);
    return *this;
  }

  /// Reads `path`, setting every bound field present there. Throws ConfigError. With
  /// `ignore_unknown`, keys this schema does not bind are skipped (reading one section of
  /// a file that has others).
  void read_file(const std::string& path, bool ignore_unknown = false) const;

  /// Applies "section.key=value" overrides (e.g. from the command line). Throws ConfigError.
  void apply_override(const std::string& assignment) const;

  const boost::program_options::options_description& options() const { return options_; }

 private:
  boost::program_options::options_description options_;
};

} // namespace touchline
