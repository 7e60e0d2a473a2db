// RobotDef and load_robot_def: the defaults every maker of a robot starts from, each INI
// file read into its part, a bad file one line naming it, and how a behaviour is named.
#include "touchline/robot/robot_def.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "touchline/ini.hpp"

namespace touchline::robot {
namespace {

const std::string kConfig = std::string(TOUCHLINE_SOURCE_DIR) + "/config/";

/// Writes `text` to a file in the test's temporary directory and returns its path.
std::string write_ini(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "robot_def_" + name + ".ini";
  std::ofstream(path) << text;
  return path;
}

/// The ConfigError message load_robot_def gives for `files`, or "" when it loads.
std::string error_for(const RobotConfigFiles& files) {
  try {
    load_robot_def(files);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(RobotDef, NoFilesGiveTheBuiltInRobot) {
  const RobotDef def = load_robot_def({});
  EXPECT_EQ(def.id, (RobotId{0, 1}));
  EXPECT_FLOAT_EQ(def.walk.period_s, 0.5f);
  EXPECT_FLOAT_EQ(def.walk.max_forward_mm_s, 300);
  EXPECT_FLOAT_EQ(def.kick.kick.peak_speed_mm_s, 1600);
  EXPECT_FLOAT_EQ(def.kick.dribble.peak_speed_mm_s, 900);
  EXPECT_FLOAT_EQ(def.head.max_yaw_rad, 2.08f);
  EXPECT_FLOAT_EQ(def.localisation.filters.field.length_mm, 6000); // SPL 2011
  EXPECT_FALSE(def.localisation.perfect);
  EXPECT_EQ(def.behaviour.name, "stand");
  EXPECT_TRUE(def.behaviour.params.empty());
  EXPECT_FALSE(def.timing.charge_cpu);
}

TEST(RobotDef, TheShippedFilesDescribeTheBuiltInRobot) {
  // config/walk.ini, kick.ini and head.ini hold the struct defaults: a robot made with them
  // (robot_shim as launched) and one made without (tests, learning) play alike.
  const RobotDef built_in;
  const RobotDef shipped =
      load_robot_def({kConfig + "walk.ini", kConfig + "kick.ini", kConfig + "spl2011.ini", kConfig + "head.ini"});
  EXPECT_EQ(shipped.walk.period_s, built_in.walk.period_s);
  EXPECT_EQ(shipped.walk.max_turn_rad_s, built_in.walk.max_turn_rad_s);
  EXPECT_EQ(shipped.walk.swing_shape, built_in.walk.swing_shape);
  for (const auto& [loaded, fixed] : {std::pair{shipped.kick.kick, built_in.kick.kick},
                                      std::pair{shipped.kick.dribble, built_in.kick.dribble}}) {
    EXPECT_EQ(loaded.prepare_s, fixed.prepare_s);
    EXPECT_EQ(loaded.backswing_mm, fixed.backswing_mm);
    EXPECT_EQ(loaded.swing_length_mm, fixed.swing_length_mm);
    EXPECT_EQ(loaded.peak_speed_mm_s, fixed.peak_speed_mm_s);
    EXPECT_EQ(loaded.min_power, fixed.min_power);
    EXPECT_EQ(loaded.reposition_speed_mm_s, fixed.reposition_speed_mm_s);
    EXPECT_EQ(loaded.aim_speed_rad_s, fixed.aim_speed_rad_s);
    EXPECT_EQ(loaded.max_bend_rad, fixed.max_bend_rad);
    EXPECT_EQ(loaded.recover_s, fixed.recover_s);
  }
  EXPECT_EQ(shipped.head.max_yaw_rad, built_in.head.max_yaw_rad);
  EXPECT_EQ(shipped.head.min_pitch_rad, built_in.head.min_pitch_rad);
  EXPECT_EQ(shipped.head.max_pitch_rad, built_in.head.max_pitch_rad);
  EXPECT_EQ(shipped.head.max_speed_rad_s, built_in.head.max_speed_rad_s);
  EXPECT_EQ(shipped.localisation.filters.field.length_mm, built_in.localisation.filters.field.length_mm);
  EXPECT_EQ(shipped.localisation.filters.field.goal_width_mm, built_in.localisation.filters.field.goal_width_mm);
}

TEST(RobotDef, EachFileIsReadIntoItsPart) {
  const RobotDef walk = load_robot_def({write_ini("walk", "[walk]\nperiod_s = 0.6\n"), "", "", ""});
  EXPECT_FLOAT_EQ(walk.walk.period_s, 0.6f);
  EXPECT_FLOAT_EQ(walk.walk.max_forward_mm_s, 300); // a key the file leaves out keeps its default
  EXPECT_FLOAT_EQ(walk.kick.kick.peak_speed_mm_s, 1600);

  const RobotDef kick = load_robot_def({"", write_ini("kick", "[kick]\npeak_speed_mm_s = 2000\n[dribble]\nrecover_s = 0.3\n"), "", ""});
  EXPECT_FLOAT_EQ(kick.kick.kick.peak_speed_mm_s, 2000);
  EXPECT_FLOAT_EQ(kick.kick.dribble.recover_s, 0.3f);
  EXPECT_FLOAT_EQ(kick.kick.dribble.peak_speed_mm_s, 900);
  EXPECT_FLOAT_EQ(kick.walk.period_s, 0.5f);

  const RobotDef field = load_robot_def({"", "", kConfig + "spl2020.ini", ""}); // the world's file, other sections skipped
  EXPECT_FLOAT_EQ(field.localisation.filters.field.length_mm, 9000);
  EXPECT_FLOAT_EQ(field.localisation.filters.field.width_mm, 6000);
  EXPECT_FLOAT_EQ(field.localisation.filters.field.goal_width_mm, 1500);
  EXPECT_FLOAT_EQ(field.localisation.filters.field.penalty_mark_distance_mm, 1300);

  const RobotDef head = load_robot_def({"", "", "", write_ini("head", "[head]\nmax_speed_rad_s = 2\n")});
  EXPECT_FLOAT_EQ(head.head.max_speed_rad_s, 2);
  EXPECT_FLOAT_EQ(head.head.max_yaw_rad, 2.08f);
}

TEST(RobotDef, WhatNoFileNamesIsKeptFromTheGivenDef) {
  RobotDef given;
  given.id = {1, 5};
  given.walk.max_forward_mm_s = 250;
  given.kick.kick.recover_s = 0.2f;
  given.localisation.perfect = true;
  given.behaviour = {"py:striker", {{"skill", "GoToBall"}}, "/somewhere"};
  const RobotDef def = load_robot_def({"", write_ini("kick_only", "[kick]\nprepare_s = 0.5\n"), "", ""}, given);
  EXPECT_EQ(def.id, (RobotId{1, 5}));
  EXPECT_FLOAT_EQ(def.walk.max_forward_mm_s, 250);
  EXPECT_FLOAT_EQ(def.kick.kick.prepare_s, 0.5f);
  EXPECT_FLOAT_EQ(def.kick.kick.recover_s, 0.4f); // a file replaces its whole part: defaults, then the file
  EXPECT_TRUE(def.localisation.perfect);
  EXPECT_EQ(def.behaviour.name, "py:striker");
  EXPECT_EQ(def.behaviour.python_dir, "/somewhere");
}

TEST(RobotDef, ABadFileIsOneLineNamingIt) {
  const std::string missing = ::testing::TempDir() + "robot_def_missing.ini";
  const std::string bad_walk = write_ini("bad_walk", "[walk]\nperiod_s = -1\n");
  const std::string bad_kick = write_ini("bad_kick", "[kick]\npeak_speed_mm_s = inf\n");
  const std::string bad_field = write_ini("bad_field", "[field]\nlength_mm = 0\n");
  const std::string bad_head = write_ini("bad_head", "[head]\nmin_pitch_rad = 0.2\n");
  const std::string unknown = write_ini("unknown", "[walk]\nspeed = 1\n");
  for (const auto& [files, path, what] : {
           std::tuple{RobotConfigFiles{missing, "", "", ""}, missing, "cannot open config file"},
           std::tuple{RobotConfigFiles{"", missing, "", ""}, missing, "cannot open config file"},
           std::tuple{RobotConfigFiles{"", "", missing, ""}, missing, "cannot open config file"},
           std::tuple{RobotConfigFiles{bad_walk, "", "", ""}, bad_walk, "walk.period_s must be in [0.02, 10] (got -1)"},
           std::tuple{RobotConfigFiles{"", bad_kick, "", ""}, bad_kick, "kick.peak_speed_mm_s must be a finite number"},
           std::tuple{RobotConfigFiles{"", "", bad_field, ""}, bad_field, "field.length_mm must be in (0, "},
           std::tuple{RobotConfigFiles{"", "", "", missing}, missing, "cannot open config file"},
           std::tuple{RobotConfigFiles{"", "", "", bad_head}, bad_head, "head.min_pitch_rad must be in [-3.1416, 0] (got 0.2)"},
           std::tuple{RobotConfigFiles{unknown, "", "", ""}, unknown, "speed"},
       }) {
    const std::string message = error_for(files);
    EXPECT_EQ(message.rfind(path, 0), 0u) << message; // starts with the file
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(BehaviourDef, PyNamesThePythonBehavioursModule) {
  EXPECT_EQ(python_module({"py", {}, ""}), "behaviour");
  EXPECT_EQ(python_module({"py:striker", {}, ""}), "striker");
  EXPECT_EQ(python_module({"GoToBall", {}, ""}), std::nullopt);
  EXPECT_EQ(python_module({"python", {}, ""}), std::nullopt); // a C++ name that happens to start with py
  try {
    python_module({"py:", {}, ""});
    ADD_FAILURE() << "py: names no module";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "py:MODULE needs a module name");
  }
}

TEST(BehaviourDef, DescribeIsTheNameAndParamsInKeyOrder) {
  EXPECT_EQ(describe({"stand", {}, ""}), "stand");
  EXPECT_EQ(describe({"py", {{"skill", "GoToBall"}, {"goal_x", "4500"}}, "/dir"}), "py goal_x=4500 skill=GoToBall");
}

} // namespace
} // namespace touchline::robot
