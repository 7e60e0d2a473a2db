// The match secret: hex of a sane length, from a file or the environment, and errors that
// say what is wrong without echoing the secret.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "touchline/lcm/match_key.hpp"

using touchline::transport::kMatchSecretVariable;
using touchline::transport::load_match_key;
using touchline::transport::MatchKey;

namespace {

std::string error_of(const std::string& hex) {
  try {
    MatchKey::from_hex(hex);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(MatchKey, ReadsHexAndWritesItBack) {
  const std::string hex = "00ff10A0" + std::string(56, '7');
  const MatchKey key = MatchKey::from_hex("  " + hex + "\n");
  EXPECT_EQ(key.bytes().size(), 32u);
  EXPECT_EQ(key.bytes()[1], 0xff);
  EXPECT_EQ(key.hex(), "00ff10a0" + std::string(56, '7'));
}

TEST(MatchKey, RefusesShortLongOddAndNonHexWithoutEchoingIt) {
  EXPECT_NE(error_of(std::string(30, 'a')).find("32 to 128 hex digits (got 30 characters)"), std::string::npos);
  EXPECT_NE(error_of(std::string(130, 'a')).find("32 to 128 hex digits"), std::string::npos);
  EXPECT_NE(error_of(std::string(33, 'a')).find("32 to 128 hex digits"), std::string::npos);
  const std::string secretish = std::string(31, 'a') + "zq";
  const std::string error = error_of(secretish + std::string(31, 'a'));
  EXPECT_NE(error.find("hex digits only"), std::string::npos) << error;
  EXPECT_EQ(error.find(secretish), std::string::npos);
}

TEST(MatchKey, RandomKeysDiffer) {
  EXPECT_NE(MatchKey::random().hex(), MatchKey::random().hex());
  EXPECT_EQ(MatchKey::random().bytes().size(), 32u);
}

TEST(MatchKey, AFileWinsOverTheEnvironment) {
  const auto file = std::filesystem::temp_directory_path() / "touchline_test_match_key.hex";
  std::ofstream(file) << std::string(64, 'c') << "\n";
  setenv(kMatchSecretVariable, std::string(64, 'd').c_str(), 1);
  EXPECT_EQ(load_match_key(file.string()).hex(), std::string(64, 'c'));
  EXPECT_EQ(load_match_key("").hex(), std::string(64, 'd'));
  std::filesystem::remove(file);
}

TEST(MatchKey, NoSecretAnywhereSaysHowToSetOne) {
  unsetenv(kMatchSecretVariable);
  try {
    load_match_key("");
    FAIL() << "loaded";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no match secret: set TOUCHLINE_MATCH_SECRET"), std::string::npos);
  }
  try {
    load_match_key("/nonexistent/key");
    FAIL() << "loaded";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "--secret-file /nonexistent/key: cannot be read");
  }
}
