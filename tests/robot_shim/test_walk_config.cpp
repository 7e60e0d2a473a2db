// load_walk_def: the shipped config/walk.ini, overrides, and one-line errors that name
// the file and the key.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

#include "touchline/ini.hpp"
#include "touchline/robot/walk_cycle.hpp"

namespace touchline::robot {
namespace {

const std::string kShippedWalk = std::string(TOUCHLINE_SOURCE_DIR) + "/config/walk.ini";

/// Writes `text` to a file in the test's temporary directory and returns its path.
std::string write_ini(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "walk_config_" + name + ".ini";
  std::ofstream(path) << text;
  return path;
}

/// The ConfigError message load_walk_def gives for `text`, or "" when it loads.
std::string error_for(const std::string& name, const std::string& text) {
  const std::string path = write_ini(name, text);
  try {
    load_walk_def(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

void expect_same(const WalkDef& a, const WalkDef& b) {
  EXPECT_EQ(a.period_s, b.period_s);
  EXPECT_EQ(a.max_forward_mm_s, b.max_forward_mm_s);
  EXPECT_EQ(a.max_backward_mm_s, b.max_backward_mm_s);
  EXPECT_EQ(a.max_left_mm_s, b.max_left_mm_s);
  EXPECT_EQ(a.max_turn_rad_s, b.max_turn_rad_s);
  EXPECT_EQ(a.accel_forward_mm_s2, b.accel_forward_mm_s2);
  EXPECT_EQ(a.accel_left_mm_s2, b.accel_left_mm_s2);
  EXPECT_EQ(a.accel_turn_rad_s2, b.accel_turn_rad_s2);
  EXPECT_EQ(a.foot_separation_mm, b.foot_separation_mm);
  EXPECT_EQ(a.double_support, b.double_support);
  EXPECT_EQ(a.swing_shape, b.swing_shape);
}

TEST(WalkConfig, ShippedFileAgreesWithTheStructDefaults) {
  expect_same(load_walk_def(kShippedWalk), WalkDef{});
}

TEST(WalkConfig, ShippedFileWritesOutEveryKeyUnderACommentInWalkSection) {
  // The file documents the walk: every WalkDef field appears, in [walk], each right
  // after a comment line (which gives its unit).
  const std::set<std::string> expected = {
      "period_s",         "max_forward_mm_s",    "max_backward_mm_s", "max_left_mm_s",
      "max_turn_rad_s",   "accel_forward_mm_s2", "accel_left_mm_s2",  "accel_turn_rad_s2",
      "foot_separation_mm", "double_support",    "swing_shape"};
  std::ifstream in(kShippedWalk);
  ASSERT_TRUE(in) << kShippedWalk;
  std::set<std::string> found;
  std::string line, previous, section;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') section = line;
    const auto eq = line.find('=');
    if (!line.empty() && line[0] != '#' && eq != std::string::npos) {
      std::string key = line.substr(0, eq);
      key.erase(key.find_last_not_of(' ') + 1);
      EXPECT_EQ(section, "[walk]") << key;
      EXPECT_EQ(previous.rfind('#', 0), 0u) << key << " has no comment line above it";
      found.insert(key);
    }
    previous = line;
  }
  EXPECT_EQ(found, expected);
}

TEST(WalkConfig, EmptyPathGivesTheDefaults) { expect_same(load_walk_def(""), WalkDef{}); }

TEST(WalkConfig, KeysInTheFileOverrideTheDefaults) {
  const WalkDef def = load_walk_def(write_ini("override", "[walk]\nperiod_s = 0.6\nswing_shape = 0\n"));
  EXPECT_FLOAT_EQ(def.period_s, 0.6f);
  EXPECT_EQ(def.swing_shape, 0);
  EXPECT_EQ(def.max_forward_mm_s, WalkDef{}.max_forward_mm_s);
}

TEST(WalkConfig, UnknownKeyIsAnErrorNamingTheKeyAndFile) {
  const std::string message = error_for("unknown", "[walk]\nperiod_s = 0.5\nstride_mm = 3\n");
  EXPECT_NE(message.find("walk.stride_mm"), std::string::npos) << message;
  EXPECT_NE(message.find("walk_config_unknown.ini"), std::string::npos) << message;
}

TEST(WalkConfig, NegativePeriodIsAnErrorNamingTheKeyAndValue) {
  const std::string message = error_for("period", "[walk]\nperiod_s = -1\n");
  EXPECT_NE(message.find("walk_config_period.ini: walk.period_s must be in [0.02, 10] (got -1)"),
            std::string::npos)
      << message;
}

TEST(WalkConfig, DoubleSupportAboveRangeIsAnError) {
  const std::string message = error_for("double_support", "[walk]\ndouble_support = 1.5\n");
  EXPECT_NE(message.find("walk.double_support"), std::string::npos) << message;
  EXPECT_NE(message.find("1.5"), std::string::npos) << message;
}

TEST(WalkConfig, OtherOutOfRangeValuesAreErrors) {
  EXPECT_NE(error_for("swing", "[walk]\nswing_shape = 2\n").find("walk.swing_shape"),
            std::string::npos);
  EXPECT_NE(error_for("accel", "[walk]\naccel_turn_rad_s2 = 0\n").find("walk.accel_turn_rad_s2"),
            std::string::npos);
  EXPECT_NE(error_for("sep", "[walk]\nfoot_separation_mm = -5\n").find("walk.foot_separation_mm"),
            std::string::npos);
  EXPECT_NE(error_for("nan", "[walk]\nperiod_s = nan\n").find("walk.period_s"), std::string::npos);
}

TEST(WalkConfig, InfiniteNanAndHugeValuesAreErrorsNamingTheKey) {
  // inf once passed "> 0"; a walk speed of 1e30 mm/s became a Box2D velocity.
  EXPECT_EQ(error_for("inf", "[walk]\nperiod_s = inf\n"),
            ::testing::TempDir() + "walk_config_inf.ini: walk.period_s must be a finite number (got 'inf')");
  EXPECT_EQ(error_for("huge", "[walk]\nmax_forward_mm_s = 1e30\n"),
            ::testing::TempDir() + "walk_config_huge.ini: walk.max_forward_mm_s must be in [0, 1000] (got 1e+30)");
  EXPECT_NE(error_for("neg_inf", "[walk]\naccel_left_mm_s2 = -inf\n").find("walk.accel_left_mm_s2"),
            std::string::npos);
  EXPECT_NE(error_for("turn", "[walk]\nmax_turn_rad_s = 100\n").find("walk.max_turn_rad_s must be in [0, 6.3]"),
            std::string::npos);
}

TEST(WalkConfig, ADirectoryIsNoWalkFile) {
  const std::string dir = std::string(TOUCHLINE_SOURCE_DIR) + "/config";
  try {
    load_walk_def(dir);
    FAIL() << "a directory read as an empty walk file";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), (dir + ": cannot open config file (it is a directory)").c_str());
  }
}

TEST(WalkConfig, SideStepsThatWouldCrossTheFeetAreAnError) {
  // 500 mm/s * 0.5 s / 2 = 125 mm of sideways step against 100 mm between the feet.
  const std::string message = error_for("cross", "[walk]\nmax_left_mm_s = 500\n");
  EXPECT_NE(message.find("walk.max_left_mm_s"), std::string::npos) << message;
  EXPECT_EQ(error_for("no_cross", "[walk]\nmax_left_mm_s = 350\n"), "");
}

TEST(WalkConfig, ValueThatIsNotANumberIsAnErrorNamingTheKey) {
  const std::string message = error_for("not_number", "[walk]\nperiod_s = fast\n");
  EXPECT_NE(message.find("walk.period_s"), std::string::npos) << message;
}

TEST(WalkConfig, MissingFileIsAnErrorNamingThePath) {
  const std::string path = ::testing::TempDir() + "no_such_walk.ini";
  try {
    load_walk_def(path);
    FAIL() << "no error for a missing file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace touchline::robot
