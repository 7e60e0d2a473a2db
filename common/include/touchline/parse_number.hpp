#pragma once
// Strict text -> number for config files and command lines. Stricter than
// boost::lexical_cast, which both used before: that reads "-1" into an unsigned by
// wrapping it to 2^64 - 1 and reads "inf" and "nan" into floats, so that a typo became a
// seed of 18446744073709551615 or a field of infinite length.
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

namespace touchline {

/// The number `text` spells, or nullopt: the whole text (surrounding blanks and one leading
/// '+' allowed) must be a base-10 integer within T's range for an integral T, or a decimal
/// or scientific number that is finite in T for a floating-point T ("nan", "inf" and
/// overflowing "1e39" for a float are refused). A '-' is refused for an unsigned T.
template <typename T>
std::optional<T> parse_number(std::string_view text) {
  static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>, "numbers only");
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) return std::nullopt;
  }
  if (text.empty() || (std::is_unsigned_v<T> && text.front() == '-')) return std::nullopt;
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) return std::nullopt;
  }
  return value;
}

/// What parse_number<T> accepts, for messages: "a finite number", "an integer".
template <typename T>
const char* number_kind() {
  return std::is_floating_point_v<T> ? "a finite number" : "an integer";
}

/// `value` as a message shows it: 0.01, 86400, 1000000, 18446744073709551615, nan.
template <typename T>
std::string format_number(T value) {
  std::ostringstream out;
  if constexpr (std::is_floating_point_v<T>) {
    if (std::isfinite(value) && value == std::trunc(value) && std::fabs(value) < 1e15) {
      out << static_cast<long long>(value); // whole numbers in full, not as 1e+06
      return out.str();
    }
    out.precision(std::numeric_limits<T>::max_digits10 - 2); // 0.1f as 0.1, not 0.100000001
  }
  out << +value; // + prints an int8_t as a number, not a character
  return out.str();
}

} // namespace touchline
