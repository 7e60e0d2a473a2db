#pragma once
// A referee on the SPL 2011 field (6000 x 4000, 65 mm ball) driven by hand-made inputs.
// With the default rules INITIAL lasts 1 s, READY 45 s and SET 5 s, so a referee first
// updated at 0 s starts PLAYING at exactly 51 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "touchline/angles.hpp"
#include "touchline/sim/referee.hpp"

namespace touchline::sim {

constexpr int64_t kSecond = 1000000;
constexpr float kBallDiameterMm = 65.f;
constexpr double kKickOffS = 51.0; ///< default rules: the first half's PLAYING begins here

inline int64_t at_s(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }

/// The modern SPL field (config/spl2020.ini's [field]): 9000 x 6000, goal 1500 wide,
/// penalty area 1650 x 4000, penalty marks 1300 in, centre circle 1500.
inline FieldDef spl2020_field() {
  FieldDef f;
  f.length_mm = 9000;
  f.width_mm = 6000;
  f.goal_width_mm = 1500;
  f.penalty_area_length_mm = 1650;
  f.penalty_area_width_mm = 4000;
  f.penalty_mark_distance_mm = 1300;
  f.centre_circle_diameter_mm = 1500;
  return f;
}

class RefereeTest : public ::testing::Test {
 protected:
  Field field{FieldDef{}};
  RulesDef rules;
  std::unique_ptr<Referee> referee;
  RefereeInput input; ///< what the next update hands in (its utime is set by update_at)

  Referee& ref() {
    if (!referee) referee = std::make_unique<Referee>(field, rules, 4, kBallDiameterMm);
    return *referee;
  }
  RefereeDecision update_at(double seconds) {
    input.utime = at_s(seconds);
    return ref().update(input);
  }
  /// First update at 0 s, then at the kick-off: PLAYING from 51 s. The robots put so far
  /// are shown only from the next update on, so that SET's manual placement leaves them be.
  void start_playing() {
    std::vector<RobotOnField> robots;
    robots.swap(input.robots);
    update_at(0);
    update_at(kKickOffS);
    robots.swap(input.robots);
    ASSERT_EQ(ref().state(), GameState::kPlaying);
  }
  void put_ball(float x, float y, float vx = 0, float vy = 0) { input.ball = BallTruth{x, y, vx, vy}; }
  void put_robot(RobotId id, float x, float y, float theta, bool active = true) {
    for (auto& r : input.robots)
      if (r.id == id) {
        r = RobotOnField{id, Pose2D{x, y, theta}, active};
        return;
      }
    input.robots.push_back(RobotOnField{id, Pose2D{x, y, theta}, active});
  }
  /// Moves a robot where the referee said (what the match will do).
  void apply(const RefereeDecision& d) {
    for (const RobotPlacement& p : d.placements) put_robot(p.robot, p.pose.x_mm, p.pose.y_mm, p.pose.theta_rad);
    if (d.ball) put_ball(d.ball->x_mm, d.ball->y_mm);
  }
};

inline bool contains(const std::vector<RobotId>& ids, RobotId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

inline void expect_pose(const Pose2D& got, float x, float y, float theta) {
  EXPECT_NEAR(got.x_mm, x, 1e-3f);
  EXPECT_NEAR(got.y_mm, y, 1e-3f);
  EXPECT_NEAR(normalise_angle(got.theta_rad - theta), 0.f, 1e-5f) << got.theta_rad << " vs " << theta;
}

} // namespace touchline::sim
