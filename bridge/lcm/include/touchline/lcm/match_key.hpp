#pragma once
// The match's shared secret. Every message on the match bus carries an HMAC-SHA-256 made
// with it (see bus.hpp), so nobody without the secret can act for a robot, refuse a join,
// end the match or feed the robots a forged frame. The launcher makes one per match and
// hands it to the programs it starts in the environment (never on the command line, where
// `ps` would show it); for programs started by hand, or on other hosts, the user sets it.
#include <cstdint>
#include <string>
#include <vector>

namespace touchline::transport {

/// The environment variable the programs read the secret from: hex, 32 to 128 digits.
constexpr const char* kMatchSecretVariable = "TOUCHLINE_MATCH_SECRET";

class MatchKey {
 public:
  /// From hex text (surrounding whitespace ignored). Throws std::invalid_argument with one
  /// line saying what is wrong (never echoing the secret).
  static MatchKey from_hex(const std::string& text);
  /// 32 fresh bytes from the operating system's random source.
  static MatchKey random();

  std::string hex() const;
  const std::vector<uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
};

/// The match key from `secret_file` (hex text) when it is not empty, else from
/// $TOUCHLINE_MATCH_SECRET. Throws std::invalid_argument, one line naming the source and
/// the fault, when neither gives a valid key.
MatchKey load_match_key(const std::string& secret_file);

} // namespace touchline::transport
