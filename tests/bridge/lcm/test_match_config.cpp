// match_config_t from the WorldConfig the world runs: what the viewer and launcher draw and
// count from, so every size must be the config's own, overrides included.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "touchline/lcm/match_config.hpp"

using namespace touchline;

TEST(MatchConfig, CarriesTheConfigTheWorldRunsWithItsOverrides) {
  const sim::WorldConfig config = sim::load_world_config(
      "", {"field.length_mm=7000", "field.border_mm=650", "camera.near_range_mm=900", "sonar.range_mm=800",
           "match.team_size=3", "physics.foot_length_mm=150"});
  const match_config_t m = transport::to_lcm(config, 42, 1000);
  EXPECT_EQ(m.types_version, int{match_config_t::TYPES_VERSION}); // lcm-gen declares the constant, never defines it
  EXPECT_EQ(m.utime, 1000);
  EXPECT_EQ(m.seed, 42);
  EXPECT_EQ(m.team_size, 3);
  EXPECT_EQ(m.field_length_mm, 7000.f);
  EXPECT_EQ(m.field_width_mm, config.field.width_mm);
  EXPECT_EQ(m.border_mm, 650.f);
  EXPECT_EQ(m.goal_width_mm, config.field.goal_width_mm);
  EXPECT_EQ(m.centre_circle_diameter_mm, config.field.centre_circle_diameter_mm);
  EXPECT_EQ(m.ball_diameter_mm, config.physics.ball_diameter_mm);
  EXPECT_EQ(m.foot_length_mm, 150.f);
  EXPECT_EQ(m.foot_separation_mm, config.match.foot_separation_mm);
  EXPECT_EQ(m.camera_field_of_view_rad, config.perception.camera.field_of_view_rad);
  EXPECT_EQ(m.camera_near_range_mm, 900.f);
  EXPECT_EQ(m.camera_range_span_mm, config.perception.camera.range_span_mm);
  EXPECT_EQ(m.sonar_range_mm, 800.f);
  EXPECT_EQ(m.duration_s, config.match.duration_s);
  EXPECT_EQ(m.half_s, config.rules.half_s);
}

TEST(MatchConfig, KeepsEverySeedBit) {
  const match_config_t m = transport::to_lcm(sim::WorldConfig{}, UINT64_MAX, 0);
  EXPECT_EQ(static_cast<uint64_t>(m.seed), UINT64_MAX);
}

// A reader built with other types cannot decode the message (its fingerprint differs) but
// must still find the writer's version where the type's comment promises: bytes 16-17.
TEST(MatchConfig, TheVersionIsTheFirstTwoBytesAfterTheFingerprint) {
  const match_config_t m = transport::to_lcm(sim::WorldConfig{}, 1, 0);
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  ASSERT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  EXPECT_EQ((bytes[16] << 8) | bytes[17], int{match_config_t::TYPES_VERSION});
}
