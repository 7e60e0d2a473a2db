// Command-line helpers: bounded numeric options and the early check of output paths.
#include "touchline/cli.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "touchline/ini.hpp"

namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace touchline {
namespace {

/// Parses `args` (after the program name) into an options_description holding `add`'s options.
template <typename Add>
std::string parse_error(const std::vector<std::string>& args, Add add) {
  po::options_description options;
  add(options.add_options());
  std::vector<const char*> argv{"program"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    po::variables_map vm;
    po::store(po::command_line_parser(static_cast<int>(argv.size()), argv.data()).options(options).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    return e.what();
  }
  return "";
}

TEST(NumberOption, StoresAValueInRange) {
  double speed = 1;
  EXPECT_EQ(parse_error({"--speed", "2.5"}, [&](auto add) { add("speed", number_option("--speed", &speed, 0.01, 1000.0)); }),
            "");
  EXPECT_EQ(speed, 2.5);
}

TEST(NumberOption, KeepsTheDefaultWhenAbsentAndShowsIt) {
  double speed = 1;
  po::options_description options;
  options.add_options()("speed", number_option("--speed", &speed, 0.01, 1000.0), "");
  EXPECT_EQ(options.find("speed", false).format_parameter(), "arg (=1)");
  EXPECT_EQ(parse_error({}, [&](auto add) { add("speed", number_option("--speed", &speed, 0.01, 1000.0)); }), "");
  EXPECT_EQ(speed, 1);
}

TEST(NumberOption, RefusesNonFiniteOutOfRangeAndGarbageNamingTheOptionAndRange) {
  double speed = 1;
  auto speed_error = [&](const std::string& text) {
    return parse_error({"--speed", text}, [&](auto add) { add("speed", number_option("--speed", &speed, 0.01, 1000.0)); });
  };
  EXPECT_EQ(speed_error("nan"), "--speed must be a number in [0.01, 1000] (got 'nan')");
  EXPECT_EQ(speed_error("inf"), "--speed must be a number in [0.01, 1000] (got 'inf')");
  EXPECT_EQ(speed_error("1e308"), "--speed must be a number in [0.01, 1000] (got '1e308')");
  EXPECT_EQ(speed_error("0"), "--speed must be a number in [0.01, 1000] (got '0')");
  EXPECT_EQ(speed_error("fast"), "--speed must be a number in [0.01, 1000] (got 'fast')");
  EXPECT_EQ(speed, 1);
}

TEST(NumberOption, AnUnsignedSeedRefusesANegativeNumberInsteadOfWrappingIt) {
  uint64_t seed = 1;
  auto seed_error = [&](const std::string& text) {
    return parse_error({"--seed", text}, [&](auto add) {
      add("seed", number_option("--seed", &seed, uint64_t{0}, std::numeric_limits<uint64_t>::max()));
    });
  };
  EXPECT_EQ(seed_error("-1"), "--seed must be an integer in [0, 18446744073709551615] (got '-1')");
  EXPECT_EQ(seed_error("1.5"), "--seed must be an integer in [0, 18446744073709551615] (got '1.5')");
  EXPECT_EQ(seed, 1u);
  EXPECT_EQ(seed_error("18446744073709551615"), "");
  EXPECT_EQ(seed, std::numeric_limits<uint64_t>::max());
}

class Writable : public testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "touchline-cli-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string error_for(const std::string& path) {
    try {
      require_writable("--summary", path);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(Writable, ANewFileIsCheckedAndNotLeftBehind) {
  EXPECT_EQ(error_for(dir_ / "summary.json"), "");
  EXPECT_FALSE(fs::exists(dir_ / "summary.json"));
}

TEST_F(Writable, AnExistingFileKeepsItsContents) {
  std::ofstream(dir_ / "summary.json") << "earlier";
  EXPECT_EQ(error_for(dir_ / "summary.json"), "");
  std::ifstream in(dir_ / "summary.json");
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "earlier");
}

TEST_F(Writable, AMissingFolderOrADirectoryIsOneLineNamingOptionAndPath) {
  const std::string missing = (dir_ / "no" / "summary.json").string();
  EXPECT_EQ(error_for(missing), "--summary " + missing + ": cannot write there (No such file or directory)");
  EXPECT_EQ(error_for(dir_.string()), "--summary " + dir_.string() + ": cannot write there (it is a directory)");
  EXPECT_EQ(error_for(""), "--summary : cannot write there (empty path)");
}

TEST_F(Writable, AFifoWithoutAReaderFailsAtOnceInsteadOfHanging) {
  const std::string fifo = (dir_ / "fifo").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_for(fifo), "--summary " + fifo + ": cannot write there (No such device or address)");
}

} // namespace
} // namespace touchline
