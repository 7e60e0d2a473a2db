#pragma once
// Reads INI files into definition structs: each field is bound to "section.key" with its
// default and a description, unknown keys and bad values are one-line errors. Numbers are
// read strictly (parse_number.hpp): a float must be finite, an integer must fit.
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <boost/program_options.hpp>

#include "touchline/parse_number.hpp"

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

/// The bound of require_positive and require_non_negative unless a key needs a tighter one.
/// No Touchline value means anything larger (1000 km in mm, 11 days in s, a million
/// Hz or 1/s), and with every value at most this, products of two stay far inside a
/// float (1e12 against 3.4e38), so no sum or square in the world overflows to infinity.
constexpr float kMaxConfigValue = 1e6f;

// Range checks for validate() functions: "<key> must be in (0, 40000] (got inf)". Written
// as !(ok) so that NaN fails too, and every range is finite, so that infinity fails as
// well (it once passed "> 0" and aborted Box2D with an infinite field).

/// A value in [min, max].
inline void require_range(const char* key, float value, float min, float max) {
  if (!(value >= min && value <= max))
    config_fail(key, "in [" + format_number(min) + ", " + format_number(max) + "]", value);
}
/// A value in (0, max].
inline void require_positive(const char* key, float value, float max = kMaxConfigValue) {
  if (!(value > 0 && value <= max)) config_fail(key, "in (0, " + format_number(max) + "]", value);
}
/// A value in [0, max].
inline void require_non_negative(const char* key, float value, float max = kMaxConfigValue) {
  require_range(key, value, 0, max);
}
/// A probability or a restitution: [0, 1].
inline void require_fraction(const char* key, float value) { require_range(key, value, 0, 1); }
/// An integer in min..max: "physics.substeps must be 1..100 (got 0)".
inline void require_count(const char* key, int value, int min, int max) {
  if (value < min || value > max) config_fail(key, format_number(min) + ".." + format_number(max), value);
}

class IniSchema {
 public:
  explicit IniSchema(const std::string& caption) : options_(caption) {}

  /// Binds `*field` to `key` ("section.name"). A read sets only the keys its source
  /// names, so files and overrides can be applied one after another. A number must be
  /// what parse_number<T> accepts (finite; an integer that fits), else the read fails
  /// with "<key> must be a finite number (got 'inf')"; validate() checks the range.
  template <typename T>
  IniSchema& bind(const char* key, T* field, const char* description) {
    namespace po = boost::program_options;
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      const std::string name = key;
      options_.add_options()(key, po::value<std::string>()->notifier([name, field](const std::string& text) {
        const auto value = parse_number<T>(text);
        if (!value) throw po::error(name + " must be " + number_kind<T>() + " (got '" + text + "')");
        *field = *value;
      }), description);
    } else {
      options_.add_options()(key, po::value<T>(field), description);
    }
    return *this;
  }

  /// Reads `path`, setting every bound field present there. Throws ConfigError, naming
  /// the path, when it is missing, unreadable or a directory, or holds a bad line. With
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
