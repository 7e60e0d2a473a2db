// The robot's landmark map: positions by the id convention of touchline/frame.hpp, and
// agreement with the world's own field geometry (the one place a test may look at both).
#include <gtest/gtest.h>

#include <fstream>

#include "touchline/ini.hpp"
#include "touchline/robot/localisation/field_map.hpp"
#include "touchline/sim/field.hpp"

namespace touchline::robot::localisation {
namespace {

void expect_at(const FieldMap& map, ObjectKind kind, int id, double x, double y) {
  const auto p = map.landmark(kind, id);
  ASSERT_TRUE(p) << static_cast<int>(kind) << " " << id;
  EXPECT_DOUBLE_EQ(p->x_mm, x) << static_cast<int>(kind) << " " << id;
  EXPECT_DOUBLE_EQ(p->y_mm, y) << static_cast<int>(kind) << " " << id;
}

TEST(FieldMap, Spl2011LandmarksFollowTheIdConvention) {
  const FieldMap map;
  // Team 0's goal at -x: its left post, seen from the centre, is at -y.
  expect_at(map, ObjectKind::kGoalPost, 0, -3000, -700);
  expect_at(map, ObjectKind::kGoalPost, 1, -3000, 700);
  expect_at(map, ObjectKind::kGoalPost, 2, 3000, 700);
  expect_at(map, ObjectKind::kGoalPost, 3, 3000, -700);
  // Corners counter-clockwise from (-x, -y).
  expect_at(map, ObjectKind::kFieldCorner, 0, -3000, -2000);
  expect_at(map, ObjectKind::kFieldCorner, 1, 3000, -2000);
  expect_at(map, ObjectKind::kFieldCorner, 2, 3000, 2000);
  expect_at(map, ObjectKind::kFieldCorner, 3, -3000, 2000);
  expect_at(map, ObjectKind::kCentreLineEnd, 0, 0, -2000);
  expect_at(map, ObjectKind::kCentreLineEnd, 1, 0, 2000);
  // Penalty marks 1800 mm in front of their goal lines; 0 is team 0's.
  expect_at(map, ObjectKind::kPenaltyMark, 0, -1200, 0);
  expect_at(map, ObjectKind::kPenaltyMark, 1, 1200, 0);
}

TEST(FieldMap, ScalesWithTheConfiguredField) {
  const FieldMap map{9000.f, 6000.f, 1500.f, 1300.f};  // config/spl2020.ini's dimensions
  expect_at(map, ObjectKind::kGoalPost, 2, 4500, 750);
  expect_at(map, ObjectKind::kFieldCorner, 2, 4500, 3000);
  expect_at(map, ObjectKind::kPenaltyMark, 0, -3200, 0);
}

TEST(FieldMap, OnlyLandmarksWithValidIdsHavePositions) {
  const FieldMap map;
  EXPECT_FALSE(map.landmark(ObjectKind::kBall, 0));
  EXPECT_FALSE(map.landmark(ObjectKind::kTeammate, 1));
  EXPECT_FALSE(map.landmark(ObjectKind::kOpponent, 1));
  EXPECT_FALSE(map.landmark(ObjectKind::kGoalPost, 4));
  EXPECT_FALSE(map.landmark(ObjectKind::kGoalPost, -1));
  EXPECT_FALSE(map.landmark(ObjectKind::kCentreLineEnd, 2));
  EXPECT_FALSE(map.landmark(ObjectKind::kPenaltyMark, 2));
  EXPECT_EQ(map.landmarks().size(), 12u);
  EXPECT_TRUE(is_landmark(ObjectKind::kFieldCorner));
  EXPECT_FALSE(is_landmark(ObjectKind::kBall));
}

TEST(FieldMap, GoalPostsAgreeWithTheWorldsField) {
  const sim::FieldDef def;
  const sim::Field field(def);
  const FieldMap map{def.length_mm, def.width_mm, def.goal_width_mm, def.penalty_mark_distance_mm};
  for (int id = 0; id < 4; ++id) {
    const Pose2D post = field.goal_post(/*defending_team=*/id / 2, /*left=*/id % 2 == 0);
    expect_at(map, ObjectKind::kGoalPost, id, post.x_mm, post.y_mm);
  }
}

} // namespace
} // namespace touchline::robot::localisation

namespace {

TEST(LoadFieldMap, ReadsTheFieldSectionOfTheWorldsConfigAndSkipsTheRest) {
  const auto map = touchline::robot::localisation::load_field_map(TOUCHLINE_SOURCE_DIR "/config/spl2020.ini");
  EXPECT_EQ(map.length_mm, 9000.f);
  EXPECT_EQ(map.width_mm, 6000.f);
  EXPECT_EQ(map.goal_width_mm, 1500.f);
  EXPECT_EQ(map.goal_box_length_mm, 600.f);
  EXPECT_EQ(map.goal_box_width_mm, 2200.f);
  EXPECT_EQ(map.penalty_area_length_mm, 1650.f);
  EXPECT_EQ(map.penalty_area_width_mm, 4000.f);
  EXPECT_EQ(map.penalty_mark_distance_mm, 1300.f);
  EXPECT_EQ(map.centre_circle_diameter_mm, 1500.f);
  EXPECT_EQ(map.ball_diameter_mm, 100.f); // [physics], the one key of it the robot knows
  const auto classic = touchline::robot::localisation::load_field_map(TOUCHLINE_SOURCE_DIR "/config/spl2011.ini");
  EXPECT_EQ(classic.length_mm, 6000.f);
  EXPECT_EQ(classic.penalty_area_length_mm, 0.f); // 2011: none
  EXPECT_EQ(classic.ball_diameter_mm, touchline::robot::localisation::FieldMap{}.ball_diameter_mm);
  EXPECT_THROW(touchline::robot::localisation::load_field_map("/nonexistent.ini"), touchline::ConfigError);
}

/// The ConfigError message load_field_map gives for a file holding `text`.
std::string field_map_error(const std::string& text) {
  const std::string path = ::testing::TempDir() + "field_map_bad.ini";
  std::ofstream(path) << text;
  try {
    touchline::robot::localisation::load_field_map(path);
  } catch (const touchline::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(LoadFieldMap, InfiniteNanHugeAndNegativeSizesAreErrorsNamingTheKey) {
  const std::string path = ::testing::TempDir() + "field_map_bad.ini";
  EXPECT_EQ(field_map_error("[field]\nlength_mm = inf\n"),
            path + ": field.length_mm must be a finite number (got 'inf')");
  EXPECT_EQ(field_map_error("[field]\nwidth_mm = nan\n"), path + ": field.width_mm must be a finite number (got 'nan')");
  EXPECT_EQ(field_map_error("[field]\nlength_mm = 1e30\n"), path + ": field.length_mm must be in (0, 30000] (got 1e+30)");
  EXPECT_EQ(field_map_error("[field]\nwidth_mm = -4000\n"), path + ": field.width_mm must be in (0, 30000] (got -4000)");
  EXPECT_EQ(field_map_error("[field]\ngoal_width_mm = 5000\n"),
            path + ": field.goal_width_mm must be in (0, 4000] (got 5000)");
  EXPECT_EQ(field_map_error("[field]\npenalty_mark_distance_mm = 4000\n"),
            path + ": field.penalty_mark_distance_mm must be in (0, 3000] (got 4000)");
  EXPECT_EQ(field_map_error("[field]\nlength_mm = 9000\ngoal_box_length_mm = 6000\n"),
            path + ": field.goal_box_length_mm must be in [0, 4500] (got 6000)");
  EXPECT_EQ(field_map_error("[physics]\nball_diameter_mm = 0\n"), path + ": physics.ball_diameter_mm must be in (0, 1000] (got 0)");
  EXPECT_EQ(field_map_error("[physics]\nball_mass_kg = inf\n"), ""); // not the robot's business: the world checks it
}

TEST(LoadFieldMap, ADirectoryIsNoConfigFile) {
  const std::string dir = TOUCHLINE_SOURCE_DIR "/config";
  try {
    touchline::robot::localisation::load_field_map(dir);
    FAIL() << "a directory read as an empty field";
  } catch (const touchline::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), dir + ": cannot open config file (it is a directory)");
  }
}

} // namespace
