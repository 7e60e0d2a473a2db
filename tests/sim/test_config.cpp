// World configs: the shipped files load and agree with the code, mistakes are one-line
// errors naming the key, and robots start where the rules put them.
#include "touchline/sim/config.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "touchline/angles.hpp"

namespace touchline::sim {
namespace {

const std::string kConfigDir = std::string(TOUCHLINE_SOURCE_DIR) + "/config/";

/// The ConfigError message of `load`, or "" if it did not throw one.
template <typename F>
std::string config_error(F load) {
  try {
    load();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string validation_error(const WorldConfig& config) {
  return config_error([&] { validate(config); });
}

TEST(Config, Spl2011FileEqualsTheCodeDefaults) {
  const WorldConfig file = load_world_config(kConfigDir + "spl2011.ini");
  const FieldDef f;
  const PhysicsDef p;
  const MatchDef m;
  EXPECT_EQ(file.field.length_mm, f.length_mm);
  EXPECT_EQ(file.field.width_mm, f.width_mm);
  EXPECT_EQ(file.field.border_mm, f.border_mm);
  EXPECT_EQ(file.field.line_width_mm, f.line_width_mm);
  EXPECT_EQ(file.field.goal_width_mm, f.goal_width_mm);
  EXPECT_EQ(file.field.goal_depth_mm, f.goal_depth_mm);
  EXPECT_EQ(file.field.goal_post_diameter_mm, f.goal_post_diameter_mm);
  EXPECT_EQ(file.field.goal_box_length_mm, f.goal_box_length_mm);
  EXPECT_EQ(file.field.goal_box_width_mm, f.goal_box_width_mm);
  EXPECT_EQ(file.field.penalty_area_length_mm, f.penalty_area_length_mm);
  EXPECT_EQ(file.field.penalty_area_width_mm, f.penalty_area_width_mm);
  EXPECT_EQ(file.field.penalty_mark_distance_mm, f.penalty_mark_distance_mm);
  EXPECT_EQ(file.field.centre_circle_diameter_mm, f.centre_circle_diameter_mm);
  EXPECT_EQ(file.physics.ball_diameter_mm, p.ball_diameter_mm);
  EXPECT_EQ(file.physics.ball_mass_kg, p.ball_mass_kg);
  EXPECT_EQ(file.physics.ball_restitution, p.ball_restitution);
  EXPECT_EQ(file.physics.ball_rolling_decel_mm_s2, p.ball_rolling_decel_mm_s2);
  EXPECT_EQ(file.physics.ball_linear_damping, p.ball_linear_damping);
  EXPECT_EQ(file.physics.foot_length_mm, p.foot_length_mm);
  EXPECT_EQ(file.physics.foot_width_mm, p.foot_width_mm);
  EXPECT_EQ(file.physics.foot_mass_kg, p.foot_mass_kg);
  EXPECT_EQ(file.physics.foot_friction, p.foot_friction);
  EXPECT_EQ(file.physics.wall_restitution, p.wall_restitution);
  EXPECT_EQ(file.physics.post_restitution, p.post_restitution);
  EXPECT_EQ(file.physics.net_restitution, p.net_restitution);
  EXPECT_EQ(file.physics.substeps, p.substeps);
  EXPECT_EQ(file.physics.velocity_iterations, p.velocity_iterations);
  EXPECT_EQ(file.physics.position_iterations, p.position_iterations);
  EXPECT_EQ(file.match.team_size, m.team_size);
  EXPECT_EQ(file.match.duration_s, m.duration_s);
  EXPECT_EQ(file.match.foot_separation_mm, m.foot_separation_mm);
}

TEST(Config, EveryBoundKeyIsInBothShippedFiles) {
  // A key left out of a file would silently take the 2011 default.
  for (const char* name : {"spl2011.ini", "spl2020.ini"}) {
    WorldConfig config;
    IniSchema schema("all");
    bind(schema, config);
    std::ifstream file(kConfigDir + name);
    ASSERT_TRUE(file) << name;
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    for (const auto& option : schema.options().options()) {
      const std::string key = option->long_name();
      const std::string line = "\n" + key.substr(key.find('.') + 1) + " = ";
      EXPECT_NE(text.find(line), std::string::npos) << name << " lacks " << key;
    }
  }
}

TEST(Config, Spl2020FileIsTheModernField) {
  const WorldConfig config = load_world_config(kConfigDir + "spl2020.ini");
  EXPECT_EQ(config.field.length_mm, 9000);
  EXPECT_EQ(config.field.width_mm, 6000);
  EXPECT_EQ(config.field.goal_width_mm, 1500);
  EXPECT_EQ(config.field.penalty_area_length_mm, 1650);
  EXPECT_EQ(config.field.penalty_area_width_mm, 4000);
  EXPECT_EQ(config.field.penalty_mark_distance_mm, 1300);
  EXPECT_EQ(config.field.centre_circle_diameter_mm, 1500);
}

TEST(Config, EmptyPathGivesTheDefaults) {
  const WorldConfig config = load_world_config("");
  EXPECT_EQ(config.field.length_mm, FieldDef{}.length_mm);
  EXPECT_EQ(config.match.team_size, MatchDef{}.team_size);
}

TEST(Config, OverridesApplyOnTopOfTheFileInOrder) {
  const WorldConfig config = load_world_config(
      kConfigDir + "spl2020.ini",
      {"match.team_size=3", "physics.substeps=4", "match.team_size=2", "field.border_mm=800"});
  EXPECT_EQ(config.match.team_size, 2); // the later override wins
  EXPECT_EQ(config.physics.substeps, 4);
  EXPECT_EQ(config.field.border_mm, 800);
  EXPECT_EQ(config.field.length_mm, 9000); // the file's values survive the overrides
  EXPECT_EQ(config.physics.ball_diameter_mm, 100);
}

TEST(Config, UnknownKeyIsAnErrorNamingIt) {
  const std::string in_override =
      config_error([] { load_world_config("", {"field.lenght_mm=9000"}); });
  EXPECT_NE(in_override.find("lenght_mm"), std::string::npos) << in_override;

  const std::string path = ::testing::TempDir() + "touchline_unknown_key.ini";
  std::ofstream(path) << "[physics]\nball_bounciness = 0.3\n";
  const std::string in_file = config_error([&] { load_world_config(path); });
  std::remove(path.c_str());
  EXPECT_NE(in_file.find("ball_bounciness"), std::string::npos) << in_file;
}

TEST(Config, MissingFileIsAnError) {
  const std::string message = config_error([] { load_world_config(kConfigDir + "no_such.ini"); });
  EXPECT_NE(message.find("no_such.ini"), std::string::npos) << message;
}

TEST(Config, UnparsableValueIsAnError) {
  const std::string message = config_error([] { load_world_config("", {"match.team_size=four"}); });
  EXPECT_NE(message.find("team_size"), std::string::npos) << message;
}

struct BadValue {
  std::string override_text;
  std::string expected_message;
};

class BadValues : public ::testing::TestWithParam<BadValue> {};

TEST_P(BadValues, AreOneLineErrorsNamingKeyAndValue) {
  const std::string message =
      config_error([] { load_world_config("", {GetParam().override_text}); });
  EXPECT_EQ(message, GetParam().expected_message);
}

INSTANTIATE_TEST_SUITE_P(
    Ranges, BadValues,
    ::testing::Values(
        BadValue{"match.team_size=9", "match.team_size must be 1..7 (got 9)"},
        BadValue{"match.team_size=0", "match.team_size must be 1..7 (got 0)"},
        BadValue{"field.length_mm=-6000", "field.length_mm must be > 0 (got -6000)"},
        BadValue{"field.width_mm=0", "field.width_mm must be > 0 (got 0)"},
        BadValue{"physics.ball_mass_kg=0", "physics.ball_mass_kg must be > 0 (got 0)"},
        BadValue{"physics.foot_mass_kg=-1", "physics.foot_mass_kg must be > 0 (got -1)"},
        BadValue{"physics.substeps=0", "physics.substeps must be >= 1 (got 0)"},
        BadValue{"physics.ball_restitution=1.5", "physics.ball_restitution must be in [0, 1] (got 1.5)"},
        BadValue{"physics.net_restitution=-0.1", "physics.net_restitution must be in [0, 1] (got -0.1)"},
        BadValue{"field.goal_width_mm=3950",
                 "field.goal_width_mm must be < field.width_mm - goal_post_diameter_mm = 3900 (got 3950)"},
        BadValue{"field.goal_box_length_mm=3000",
                 "field.goal_box_length_mm must be < half field.length_mm = 3000 (got 3000)"},
        BadValue{"field.goal_box_width_mm=4100",
                 "field.goal_box_width_mm must be <= field.width_mm = 4000 (got 4100)"},
        BadValue{"field.goal_depth_mm=700",
                 "field.goal_depth_mm must be < field.border_mm = 700 (got 700)"},
        BadValue{"physics.ball_diameter_mm=nan", "physics.ball_diameter_mm must be > 0 (got nan)"}));

TEST(Config, ValidateAcceptsBothShippedFiles) {
  for (const char* name : {"spl2011.ini", "spl2020.ini"})
    EXPECT_EQ(validation_error(load_world_config(kConfigDir + name)), "") << name;
}

// --- initial poses ----------------------------------------------------------------------

/// The four corners of a foot (length along its heading).
std::array<std::array<float, 2>, 4> foot_corners(const Pose2D& p, float length, float width) {
  std::array<std::array<float, 2>, 4> c{};
  const float cs = std::cos(p.theta_rad), sn = std::sin(p.theta_rad);
  const float hx[] = {length / 2, length / 2, -length / 2, -length / 2};
  const float hy[] = {width / 2, -width / 2, -width / 2, width / 2};
  for (std::size_t i = 0; i < 4; ++i)
    c[i] = {p.x_mm + cs * hx[i] - sn * hy[i], p.y_mm + sn * hx[i] + cs * hy[i]};
  return c;
}

/// Feet of a robot standing at `body` (as World::add_robot puts them).
std::array<Pose2D, 2> feet(const Pose2D& body, float separation) {
  const float ox = -std::sin(body.theta_rad) * separation / 2;
  const float oy = std::cos(body.theta_rad) * separation / 2;
  return {Pose2D{body.x_mm + ox, body.y_mm + oy, body.theta_rad},
          Pose2D{body.x_mm - ox, body.y_mm - oy, body.theta_rad}};
}

class InitialPoses : public ::testing::TestWithParam<const char*> {};

TEST_P(InitialPoses, StandOnTheirOwnTouchlineOnTheCarpetApartFacingIn) {
  const WorldConfig config = load_world_config(kConfigDir + GetParam());
  const Field field(config.field);
  const PhysicsDef& p = config.physics;
  const float sep = config.match.foot_separation_mm;
  // A robot's footprint fits in a circle of this radius about its body centre.
  const float reach = std::hypot(p.foot_length_mm / 2, sep / 2 + p.foot_width_mm / 2);
  for (int n = 1; n <= kMaxTeamSize; ++n) {
    std::vector<Pose2D> placed;
    for (int team : {0, 1})
      for (int player = 1; player <= n; ++player) {
        const Pose2D pose = initial_pose(field, n, RobotId{team, player});
        SCOPED_TRACE("team size " + std::to_string(n) + ", team " + std::to_string(team) +
                     ", player " + std::to_string(player));
        // On its own half, on the touchline, facing into the field.
        EXPECT_EQ(pose.x_mm < 0, team == 0);
        EXPECT_NEAR(std::fabs(pose.y_mm), field.half_width(), 1e-3f);
        const float into_field = -pose.y_mm * std::sin(pose.theta_rad);
        EXPECT_GT(into_field, 0) << "faces out of the field";
        EXPECT_NEAR(std::fabs(std::sin(pose.theta_rad)), 1, 1e-6f);
        // Between the centre circle and the goal box, along the touchline.
        EXPECT_GT(std::fabs(pose.x_mm), config.field.centre_circle_diameter_mm / 2);
        EXPECT_LT(std::fabs(pose.x_mm), field.half_length() - config.field.goal_box_length_mm);
        for (const Pose2D& foot : feet(pose, sep))
          for (const auto& corner : foot_corners(foot, p.foot_length_mm, p.foot_width_mm))
            EXPECT_TRUE(field.on_carpet(corner[0], corner[1]));
        for (const Pose2D& other : placed)
          EXPECT_GT(std::hypot(pose.x_mm - other.x_mm, pose.y_mm - other.y_mm), 2 * reach);
        placed.push_back(pose);
      }
  }
}

INSTANTIATE_TEST_SUITE_P(BothFields, InitialPoses, ::testing::Values("spl2011.ini", "spl2020.ini"));

TEST(InitialPose, KeeperIsNearestItsOwnGoalAndTeamsMirror) {
  const Field field;
  const Pose2D red1 = initial_pose(field, 4, RobotId{0, 1});
  const Pose2D red4 = initial_pose(field, 4, RobotId{0, 4});
  const Pose2D blue1 = initial_pose(field, 4, RobotId{1, 1});
  EXPECT_LT(red1.x_mm, red4.x_mm);
  EXPECT_FLOAT_EQ(red1.y_mm, -field.half_width());
  EXPECT_FLOAT_EQ(red1.theta_rad, kPi / 2);
  EXPECT_FLOAT_EQ(blue1.x_mm, -red1.x_mm);
  EXPECT_FLOAT_EQ(blue1.y_mm, -red1.y_mm);
  EXPECT_NEAR(normalise_angle(blue1.theta_rad - red1.theta_rad - kPi), 0, 1e-6f);
}

} // namespace
TEST(Config, BallStartOffTheCarpetIsAnError) {
  try {
    load_world_config("", {"match.ball_start_x_mm=5000"});
    FAIL() << "accepted a ball outside the walls";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("match.ball_start_x_mm/_y_mm must be on the carpet"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(load_world_config("", {"match.ball_start_x_mm=3200"})); // on the border carpet
}

} // namespace touchline::sim
