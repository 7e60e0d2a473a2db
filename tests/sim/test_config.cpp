// World configs: the shipped files load and agree with the code, mistakes are one-line
// errors naming the key, and robots start where the rules put them.
#include "touchline/sim/config.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

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

TEST(Config, UnknownKeyNamesWhatWouldBeRight) {
  // The section's own keys for a misspelt key; the sections for a misspelt section.
  const std::string key = config_error([] { load_world_config("", {"field.lenght_mm=9000"}); });
  EXPECT_NE(key.find("(the keys of [field]: length_mm, width_mm,"), std::string::npos) << key;
  EXPECT_EQ(key.find("ball_diameter_mm"), std::string::npos) << key;
  const std::string section = config_error([] { load_world_config("", {"feild.length_mm=9000"}); });
  EXPECT_NE(section.find("(the sections: field, physics, match, camera, noise, sonar, touch, inertial, rules, comm)"),
            std::string::npos)
      << section;
}

TEST(Config, MissingFileIsAnError) {
  const std::string message = config_error([] { load_world_config(kConfigDir + "no_such.ini"); });
  EXPECT_EQ(message, kConfigDir + "no_such.ini: cannot open config file (No such file or directory)");
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
        BadValue{"field.length_mm=-6000", "field.length_mm must be in (0, 30000] (got -6000)"},
        BadValue{"field.width_mm=0", "field.width_mm must be in (0, 30000] (got 0)"},
        BadValue{"physics.ball_mass_kg=0", "physics.ball_mass_kg must be in [0.001, 10] (got 0)"},
        BadValue{"physics.foot_mass_kg=-1", "physics.foot_mass_kg must be in [0.01, 100] (got -1)"},
        BadValue{"physics.substeps=0", "physics.substeps must be 1..100 (got 0)"},
        BadValue{"physics.ball_restitution=1.5", "physics.ball_restitution must be in [0, 1] (got 1.5)"},
        BadValue{"physics.net_restitution=-0.1", "physics.net_restitution must be in [0, 1] (got -0.1)"},
        BadValue{"match.foot_separation_mm=400",
                 "match.foot_separation_mm must be <= physics.max_foot_spread_mm (got 400 > 300)"},
        BadValue{"physics.max_foot_spread_mm=5", "physics.max_foot_spread_mm must be in [10, 1000] (got 5)"},
        BadValue{"field.goal_width_mm=3950",
                 "field.goal_width_mm must be < field.width_mm - goal_post_diameter_mm = 3900 (got 3950)"},
        BadValue{"field.goal_box_length_mm=3000",
                 "field.goal_box_length_mm must be < half field.length_mm = 3000 (got 3000)"},
        BadValue{"field.goal_box_width_mm=4100",
                 "field.goal_box_width_mm must be <= field.width_mm = 4000 (got 4100)"},
        BadValue{"field.goal_depth_mm=700",
                 "field.goal_depth_mm must be < field.border_mm = 700 (got 700)"},
        // Values that once passed: an infinite field aborted Box2D, an infinite ball mass
        // made the truth NaN. Neither parses now, nor does a number that does not fit.
        BadValue{"field.length_mm=inf",
                 "override 'field.length_mm=inf': field.length_mm must be a finite number (got 'inf')"},
        BadValue{"physics.ball_mass_kg=inf",
                 "override 'physics.ball_mass_kg=inf': physics.ball_mass_kg must be a finite number (got 'inf')"},
        BadValue{"physics.ball_diameter_mm=nan",
                 "override 'physics.ball_diameter_mm=nan': physics.ball_diameter_mm must be a finite number (got 'nan')"},
        BadValue{"physics.foot_friction=-inf",
                 "override 'physics.foot_friction=-inf': physics.foot_friction must be a finite number (got '-inf')"},
        BadValue{"field.width_mm=1e39",
                 "override 'field.width_mm=1e39': field.width_mm must be a finite number (got '1e39')"},
        BadValue{"physics.substeps=99999999999",
                 "override 'physics.substeps=99999999999': physics.substeps must be an integer (got '99999999999')"},
        BadValue{"match.team_size=2.5",
                 "override 'match.team_size=2.5': match.team_size must be an integer (got '2.5')"},
        // Finite but absurd: bounds that keep Box2D within what it handles.
        BadValue{"field.length_mm=1e30", "field.length_mm must be in (0, 30000] (got 1e+30)"},
        BadValue{"physics.ball_mass_kg=1e6", "physics.ball_mass_kg must be in [0.001, 10] (got 1e+06)"},
        BadValue{"physics.foot_length_mm=0.001", "physics.foot_length_mm must be in [10, 1000] (got 0.001)"},
        BadValue{"physics.substeps=1000000", "physics.substeps must be 1..100 (got 1000000)"},
        BadValue{"rules.half_s=1e30", "rules.half_s must be in (0, 1000000] (got 1e+30)"},
        BadValue{"comm.max_bytes=40000", "comm.max_bytes must be 0..32767 (got 40000)"}));

/// Whether a ConfigError `message` names `key` (the ball's start is checked as a pair).
bool names_key(const std::string& message, const std::string& key) {
  if (message.find(key) != std::string::npos) return true;
  return key.rfind("match.ball_start_", 0) == 0 && message.find("match.ball_start_x_mm/_y_mm") != std::string::npos;
}

TEST(Config, EveryKeyRefusesInfinityNanAndHugeValuesNamingTheKey) {
  WorldConfig config;
  IniSchema schema("all");
  bind(schema, config);
  for (const auto& option : schema.options().options()) {
    const std::string key = option->long_name();
    for (const char* value : {"inf", "-inf", "nan", "1e30", "-1e30", "1e300"}) {
      const std::string message = config_error([&] { load_world_config("", {key + "=" + value}); });
      EXPECT_TRUE(names_key(message, key)) << key << "=" << value << ": '" << message << "'";
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

TEST(Config, ValidateRefusesNonFiniteValuesSetInCode) {
  // In-process and learning runs build a WorldConfig in code, past the file reader.
  WorldConfig config;
  config.field.length_mm = INFINITY;
  EXPECT_EQ(validation_error(config), "field.length_mm must be in (0, 30000] (got inf)");
  config = WorldConfig{};
  config.physics.ball_mass_kg = INFINITY;
  EXPECT_EQ(validation_error(config), "physics.ball_mass_kg must be in [0.001, 10] (got inf)");
  config = WorldConfig{};
  config.rules.ready_s = NAN;
  EXPECT_EQ(validation_error(config), "rules.ready_s must be in [0, 1000000] (got nan)");
  config = WorldConfig{};
  config.perception.camera.min_pitch_rad = -INFINITY;
  EXPECT_NE(validation_error(config).find("camera.min_pitch_rad"), std::string::npos);
}

TEST(Config, ADirectoryIsNoConfigFile) {
  const std::string message = config_error([] { load_world_config(kConfigDir); });
  EXPECT_EQ(message, kConfigDir + ": cannot open config file (it is a directory)");
}

TEST(Config, AnUnreadableFileIsAnErrorNamingItAndWhy) {
  const std::string path = ::testing::TempDir() + "touchline_unreadable.ini";
  std::ofstream(path) << "[match]\nteam_size = 2\n";
  ASSERT_EQ(::chmod(path.c_str(), 0), 0);
  const bool root_reads_anyway = static_cast<bool>(std::ifstream(path)); // root ignores the mode
  const std::string message = config_error([&] { load_world_config(path); });
  std::remove(path.c_str());
  if (root_reads_anyway) GTEST_SKIP() << "running as root: every file is readable";
  EXPECT_EQ(message, path + ": cannot open config file (Permission denied)");
}

TEST(Config, ValidateAcceptsBothShippedFiles) {
  for (const char* name : {"spl2011.ini", "spl2020.ini"})
    EXPECT_EQ(validation_error(load_world_config(kConfigDir + name)), "") << name;
}

// --- the bounds keep Box2D sane -------------------------------------------------------

/// Two robots drive their feet at 3000 mm/s (the fastest foot motion the robot side
/// sends) into each other and a fast ball for 3 s: every body must stay finite and inside
/// the walls, whatever values within the bounds the config holds.
void expect_world_stays_sane(const std::vector<std::string>& overrides) {
  SCOPED_TRACE(::testing::PrintToString(overrides));
  const WorldConfig config = load_world_config("", overrides);
  World world(config.field, config.physics, config.match.foot_separation_mm);
  world.add_robot({0, 1}, {-300, 0, 0});
  world.add_robot({1, 1}, {300, 0, kPi});
  world.place_ball(0, 50, 10000, 3000);
  const Field& field = world.field();
  const float reach_x = field.half_length() + config.field.border_mm + config.physics.foot_length_mm;
  const float reach_y = field.half_width() + config.field.border_mm + config.physics.foot_length_mm;
  auto sane = [&](float x, float y) {
    return std::isfinite(x) && std::isfinite(y) && std::fabs(x) <= reach_x && std::fabs(y) <= reach_y;
  };
  const FootMotion push{30, 0, 0.05f};
  for (int tick = 0; tick < 300; ++tick) {
    world.step({TickMotion{push, push}, TickMotion{push, push}});
    const BallTruth ball = world.ball();
    ASSERT_TRUE(sane(ball.x_mm, ball.y_mm) && std::isfinite(ball.vx_mm_s) && std::isfinite(ball.vy_mm_s))
        << "tick " << tick << ": ball at " << ball.x_mm << ", " << ball.y_mm;
    for (int r = 0; r < 2; ++r) {
      const RobotTruth truth = world.robot(r);
      for (const Pose2D& foot : {truth.left_foot, truth.right_foot})
        ASSERT_TRUE(sane(foot.x_mm, foot.y_mm) && std::isfinite(foot.theta_rad))
            << "tick " << tick << ": robot " << r << " foot at " << foot.x_mm << ", " << foot.y_mm;
    }
  }
}

TEST(Config, ExtremeValuesWithinTheBoundsKeepTheWorldSane) {
  const std::vector<std::string> bouncy = {"physics.ball_restitution=1", "physics.wall_restitution=1",
                                           "physics.post_restitution=1", "physics.net_restitution=1"};
  auto with = [&](std::vector<std::string> more) {
    more.insert(more.end(), bouncy.begin(), bouncy.end());
    return more;
  };
  // Everything at its largest, the feet as light as allowed.
  expect_world_stays_sane(with({"field.length_mm=30000", "field.width_mm=30000", "field.border_mm=5000",
                                "physics.ball_diameter_mm=1000", "physics.ball_mass_kg=10",
                                "physics.foot_length_mm=1000", "physics.foot_width_mm=1000",
                                "physics.foot_mass_kg=0.01", "physics.ball_rolling_decel_mm_s2=100000",
                                "physics.ball_linear_damping=100", "physics.foot_friction=10",
                                "physics.substeps=100", "physics.velocity_iterations=100",
                                "physics.position_iterations=100", "physics.max_foot_spread_mm=1000",
                                "match.foot_separation_mm=1000"}));
  // Everything at its smallest, the feet as heavy as allowed (mass ratio 1e5).
  expect_world_stays_sane(with({"physics.ball_diameter_mm=10", "physics.ball_mass_kg=0.001",
                                "physics.foot_length_mm=10", "physics.foot_width_mm=10",
                                "physics.foot_mass_kg=100", "physics.ball_rolling_decel_mm_s2=0",
                                "physics.ball_linear_damping=0", "physics.foot_friction=0",
                                "physics.substeps=1", "physics.velocity_iterations=1",
                                "physics.position_iterations=1", "physics.max_foot_spread_mm=10",
                                "match.foot_separation_mm=0.001"}));
  // A heavy ball among the lightest feet, and the smallest field the rules allow around the goal.
  expect_world_stays_sane(with({"physics.ball_mass_kg=10", "physics.foot_mass_kg=0.01",
                                "field.length_mm=1300", "field.width_mm=2300", "field.border_mm=600",
                                "field.penalty_mark_distance_mm=600", "field.centre_circle_diameter_mm=200"}));
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
