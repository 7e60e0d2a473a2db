#include "touchline/lcm/match_key.hpp"

#include <openssl/rand.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace touchline::transport {

namespace {

// 16 bytes is the least HMAC-SHA-256 should be keyed with; 64 is its block size.
constexpr size_t kMinKeyBytes = 16;
constexpr size_t kMaxKeyBytes = 64;

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string trimmed(const std::string& text) {
  size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return text.substr(begin, end - begin);
}

} // namespace

MatchKey MatchKey::from_hex(const std::string& text) {
  const std::string hex = trimmed(text);
  if (hex.size() % 2 != 0 || hex.size() < 2 * kMinKeyBytes || hex.size() > 2 * kMaxKeyBytes)
    throw std::invalid_argument("the match secret must be " + std::to_string(2 * kMinKeyBytes) + " to " +
                                std::to_string(2 * kMaxKeyBytes) + " hex digits (got " +
                                std::to_string(hex.size()) + " characters)");
  MatchKey key;
  key.bytes_.reserve(hex.size() / 2);
  for (size_t i = 0; i < hex.size(); i += 2) {
    const int high = hex_value(hex[i]), low = hex_value(hex[i + 1]);
    if (high < 0 || low < 0) throw std::invalid_argument("the match secret must be hex digits only (0-9, a-f)");
    key.bytes_.push_back(static_cast<uint8_t>(high * 16 + low));
  }
  return key;
}

MatchKey MatchKey::random() {
  MatchKey key;
  key.bytes_.resize(32);
  if (RAND_bytes(key.bytes_.data(), static_cast<int>(key.bytes_.size())) != 1)
    throw std::runtime_error("cannot draw a match secret from the system's random source");
  return key;
}

std::string MatchKey::hex() const {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (uint8_t b : bytes_) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

MatchKey load_match_key(const std::string& secret_file) {
  if (!secret_file.empty()) {
    std::ifstream in(secret_file);
    if (!in) throw std::invalid_argument("--secret-file " + secret_file + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    try {
      return MatchKey::from_hex(text.str());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--secret-file " + secret_file + ": " + e.what());
    }
  }
  const char* value = std::getenv(kMatchSecretVariable);
  if (!value || !*value)
    throw std::invalid_argument(std::string("no match secret: set ") + kMatchSecretVariable +
                                " (e.g. export " + kMatchSecretVariable +
                                "=$(openssl rand -hex 32)) or pass --secret-file; every program of the "
                                "match needs the same one");
  try {
    return MatchKey::from_hex(value);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(kMatchSecretVariable) + ": " + e.what());
  }
}

} // namespace touchline::transport
