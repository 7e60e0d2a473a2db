// The [camera], [noise] and [sonar] sections: the shipped files carry every key with the
// code's defaults, and bad values are one-line errors naming the key.
#include "touchline/sim/perception_config.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "touchline/sim/config.hpp"

namespace touchline::sim {
namespace {

const std::string kConfigDir = std::string(TOUCHLINE_SOURCE_DIR) + "/config/";

/// Reads a shipped file with every section bound (the files hold [field] etc. too).
PerceptionDef read(const std::string& name) { return load_world_config(kConfigDir + name).perception; }

TEST(PerceptionConfig, ShippedFilesHoldTheCodeDefaults) {
  const PerceptionDef d;
  for (const char* name : {"spl2011.ini", "spl2020.ini"}) {
    SCOPED_TRACE(name);
    const PerceptionDef f = read(name);
    EXPECT_EQ(f.camera.field_of_view_rad, d.camera.field_of_view_rad);
    EXPECT_EQ(f.camera.min_pitch_rad, d.camera.min_pitch_rad);
    EXPECT_EQ(f.camera.max_pitch_rad, d.camera.max_pitch_rad);
    EXPECT_EQ(f.camera.near_range_mm, d.camera.near_range_mm);
    EXPECT_EQ(f.camera.range_span_mm, d.camera.range_span_mm);
    EXPECT_EQ(f.occluder_radius_mm, d.occluder_radius_mm);
    EXPECT_EQ(f.noise.distance_sd_mm, d.noise.distance_sd_mm);
    EXPECT_EQ(f.noise.distance_sd_fraction, d.noise.distance_sd_fraction);
    EXPECT_EQ(f.noise.bearing_sd_rad, d.noise.bearing_sd_rad);
    EXPECT_EQ(f.noise.bearing_sd_rad_per_m, d.noise.bearing_sd_rad_per_m);
    EXPECT_EQ(f.noise.ball_miss_probability, d.noise.ball_miss_probability);
    EXPECT_EQ(f.noise.landmark_miss_probability, d.noise.landmark_miss_probability);
    EXPECT_EQ(f.noise.robot_miss_probability, d.noise.robot_miss_probability);
    EXPECT_EQ(f.noise.phantom_ball_probability, d.noise.phantom_ball_probability);
    EXPECT_EQ(f.noise.phantom_ball_max_distance_mm, d.noise.phantom_ball_max_distance_mm);
    EXPECT_EQ(f.sonar.range_mm, d.sonar.range_mm);
    EXPECT_EQ(f.sonar.half_width_mm, d.sonar.half_width_mm);
    EXPECT_EQ(f.sonar_noise_sd_mm, d.sonar_noise_sd_mm);
    EXPECT_EQ(f.sonar_sees_goal_posts, d.sonar_sees_goal_posts);
    EXPECT_EQ(f.touch.distance_mm, d.touch.distance_mm);
    EXPECT_EQ(f.touch.post_distance_mm, d.touch.post_distance_mm);
    EXPECT_NO_THROW(validate(f));
  }
}

TEST(PerceptionConfig, EveryKeyIsInBothShippedFiles) {
  PerceptionDef def;
  IniSchema schema("perception");
  bind(schema, def);
  for (const char* name : {"spl2011.ini", "spl2020.ini"}) {
    std::ifstream file(kConfigDir + name);
    ASSERT_TRUE(file) << name;
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    for (const auto& option : schema.options().options()) {
      const std::string key = option->long_name();
      const std::string section = "\n[" + key.substr(0, key.find('.')) + "]\n";
      const std::string line = "\n" + key.substr(key.find('.') + 1) + " = ";
      const auto at = text.find(section);
      ASSERT_NE(at, std::string::npos) << name << " lacks " << section;
      EXPECT_NE(text.find(line, at), std::string::npos) << name << " lacks " << key;
    }
  }
}

/// The ConfigError message of validating `def` after `override`, or "".
std::string error_after(const std::string& override) {
  PerceptionDef def;
  IniSchema schema("perception");
  bind(schema, def);
  try {
    schema.apply_override(override);
    validate(def);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(PerceptionConfig, BadValuesAreOneLineErrorsNamingTheKey) {
  EXPECT_EQ(error_after("noise.ball_miss_probability=1.5"), "noise.ball_miss_probability must be in [0, 1] (got 1.5)");
  EXPECT_EQ(error_after("noise.robot_miss_probability=-0.1"),
            "noise.robot_miss_probability must be in [0, 1] (got -0.1)");
  EXPECT_EQ(error_after("noise.distance_sd_fraction=-1"),
            "noise.distance_sd_fraction must be in [0, 1000000] (got -1)");
  EXPECT_EQ(error_after("noise.bearing_sd_rad=nan"),
            "override 'noise.bearing_sd_rad=nan': noise.bearing_sd_rad must be a finite number (got 'nan')");
  EXPECT_EQ(error_after("camera.max_pitch_rad=1e30"), "camera.max_pitch_rad must be in [-3.141593, 3.141593] (got 1e+30)");
  EXPECT_EQ(error_after("camera.field_of_view_rad=4"), "camera.field_of_view_rad must be in (0, pi) (got 4)");
  EXPECT_NE(error_after("camera.min_pitch_rad=0.6").find("camera.min_pitch_rad must be < camera.max_pitch_rad"),
            std::string::npos);
  EXPECT_EQ(error_after("sonar.range_mm=0"), "sonar.range_mm must be in (0, 1000000] (got 0)");
  EXPECT_EQ(error_after("camera.occluder_radius_mm=0"), ""); // 0 switches occlusion off
  EXPECT_EQ(error_after("sonar.sees_goal_posts=false"), "");
  EXPECT_EQ(error_after("inertial.gyro_turn_sd_rad=-0.001"),
            "inertial.gyro_turn_sd_rad must be in [0, 1] (got -0.001)");
  EXPECT_EQ(error_after("inertial.gyro_turn_sd_rad=0"), ""); // the body's exact turn
  EXPECT_NE(error_after("sonar.sees_goal_posts=maybe").find("sonar.sees_goal_posts"), std::string::npos);
}

} // namespace
} // namespace touchline::sim
