#pragma once
// Command-line checks both programs share: numeric options read strictly and bounded,
// output paths checked before a match starts. Every failure is one line naming the option.
#include <string>

#include <boost/program_options.hpp>

#include "touchline/parse_number.hpp"

namespace touchline {

/// A numeric option whose text must be a finite number (an integer for an integral T) in
/// [min, max]; on notify it is stored in `*field`. Anything else throws po::error
/// "--speed must be a number in [0.01, 1000] (got 'nan')": boost's own parsing let NaN
/// and infinity through and wrapped "-1" into an unsigned. With `show_default`, --help
/// shows `*field` as the default (leave it off where absence means something else).
template <typename T>
boost::program_options::typed_value<std::string>* number_option(const std::string& option, T* field, T min, T max,
                                                                bool show_default = true) {
  namespace po = boost::program_options;
  auto* value = po::value<std::string>()->notifier([option, field, min, max](const std::string& text) {
    const auto parsed = parse_number<T>(text);
    if (!parsed || *parsed < min || *parsed > max)
      throw po::error(option + " must be " + (std::is_floating_point_v<T> ? "a number" : "an integer") + " in [" +
                      format_number(min) + ", " + format_number(max) + "] (got '" + text + "')");
    *field = *parsed;
  });
  if (show_default) value->default_value(format_number(*field));
  return value;
}

/// Throws ConfigError "--summary /x/y.json: cannot write there (Permission denied)" unless
/// `path` can be written: an existing file is opened for appending (its contents are left
/// alone), a new one is created and removed again, so that a run that fails before its
/// end leaves nothing behind. For outputs written only at the end of a match, which
/// otherwise learned of a bad path after the whole match.
void require_writable(const std::string& option, const std::string& path);

} // namespace touchline
