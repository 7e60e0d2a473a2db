// Where the referee puts robots: kick-off positions (READY's targets, SET's manual
// placement), benches, re-entry spots; on both shipped fields.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "referee_fixture.hpp"

namespace touchline::sim {
namespace {

float distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x_mm - b.x_mm, a.y_mm - b.y_mm); }

// --- hand-worked on the 2011 field -----------------------------------------------------

TEST_F(RefereeTest, KickOffPositionsOnThe2011Field) {
  // Goal box front at x = -2400, centre circle radius 600: field players stand at
  // x = -2400 + u * 1800.
  expect_pose(ref().kickoff_position({0, 1}, true), -2700.f, 0.f, 0.f); // mid goal box
  expect_pose(ref().kickoff_position({0, 2}, true), -300.f, 0.f, 0.f);  // behind the ball
  expect_pose(ref().kickoff_position({0, 2}, false), -850.f, 0.f, 0.f); // 250 outside the circle
  expect_pose(ref().kickoff_position({0, 3}, true), -1500.f, 800.f, 0.f);
  expect_pose(ref().kickoff_position({0, 4}, true), -1500.f, -800.f, 0.f);
  expect_pose(ref().kickoff_position({0, 5}, true), -2040.f, 0.f, 0.f);
  expect_pose(ref().kickoff_position({0, 7}, false), -870.f, -1400.f, 0.f);
  expect_pose(ref().kickoff_position({1, 3}, true), 1500.f, -800.f, kPi); // turned about the centre
}

TEST_F(RefereeTest, BenchesAndReEntrySpotsOnThe2011Field) {
  expect_pose(ref().bench_position({0, 1}), -600.f, -2350.f, kPi / 2); // team size 4: x = -3000 * p / 5
  expect_pose(ref().bench_position({0, 4}), -2400.f, -2350.f, kPi / 2);
  expect_pose(ref().bench_position({1, 4}), 2400.f, 2350.f, -kPi / 2);
  // Ball on the centre spot: both touchlines equally far, the team's own side.
  expect_pose(ref().reentry_position({0, 3}, 0.f, 0.f), -1200.f, -2000.f, kPi / 2);
  expect_pose(ref().reentry_position({1, 3}, 0.f, 0.f), 1200.f, 2000.f, -kPi / 2);
  expect_pose(ref().reentry_position({1, 3}, 0.f, 1.f), 1200.f, -2000.f, kPi / 2);
}

// --- properties on both fields ---------------------------------------------------------

class Positions : public ::testing::TestWithParam<std::string> {
 protected:
  Positions() : field(GetParam() == "spl2011" ? FieldDef{} : spl2020_field()), referee(field, RulesDef{}, 7, 65.f) {}
  Field field;
  Referee referee;
};

TEST_P(Positions, KickOffPositionsAreLegalAndApart) {
  for (bool team0_kicks : {true, false}) {
    std::vector<Pose2D> all;
    for (int team : {0, 1}) {
      const bool kicking = (team == 0) == team0_kicks;
      for (int player = 1; player <= kMaxTeamSize; ++player) {
        const RobotId id{team, player};
        const Pose2D p = referee.kickoff_position(id, kicking);
        EXPECT_TRUE(referee.legal_kickoff_position(id, p, kicking)) << team << "/" << player;
        EXPECT_EQ(field.in_goal_box(team, p.x_mm, p.y_mm), player == 1) << team << "/" << player;
        // Facing the opponents' goal.
        EXPECT_NEAR(std::cos(p.theta_rad), team == 0 ? 1.f : -1.f, 1e-6f);
        // Team 1's picture is team 0's turned about the centre spot.
        const Pose2D mirror = referee.kickoff_position(RobotId{1 - team, player}, kicking);
        EXPECT_NEAR(p.x_mm, -mirror.x_mm, 1e-3f);
        EXPECT_NEAR(p.y_mm, -mirror.y_mm, 1e-3f);
        all.push_back(p);
      }
    }
    // Nobody starts in contact with anybody (the pushing heuristic's 300 mm).
    for (size_t i = 0; i < all.size(); ++i)
      for (size_t j = i + 1; j < all.size(); ++j)
        EXPECT_GT(distance(all[i], all[j]), 2 * CollisionDef{}.contact_distance_mm) << i << " " << j;
  }
}

TEST_P(Positions, BenchesAreOffTheFieldOnTheCarpetAndApart) {
  std::vector<Pose2D> all;
  for (int team : {0, 1}) {
    for (int player = 1; player <= kMaxTeamSize; ++player) {
      const Pose2D p = referee.bench_position(RobotId{team, player});
      EXPECT_FALSE(field.inside_lines(p.x_mm, p.y_mm));
      EXPECT_TRUE(field.on_carpet(p.x_mm, p.y_mm));
      EXPECT_LT(p.x_mm * (team == 0 ? 1.f : -1.f), 0.f); // beside the own half
      // Facing into the field.
      EXPECT_NEAR(std::sin(p.theta_rad), p.y_mm < 0 ? 1.f : -1.f, 1e-6f);
      all.push_back(p);
    }
  }
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) EXPECT_GT(distance(all[i], all[j]), 300.f);
}

TEST_P(Positions, ReEntryIsOnTheOwnHalfsTouchlineFarFromTheBall) {
  const FieldDef& f = field.def();
  for (int team : {0, 1}) {
    for (float ball_y : {-1000.f, 1000.f}) {
      const Pose2D p = referee.reentry_position(RobotId{team, 2}, 500.f, ball_y);
      EXPECT_NEAR(std::fabs(p.x_mm), f.length_mm / 2 - f.penalty_mark_distance_mm, 1e-3f);
      EXPECT_LT(p.x_mm * (team == 0 ? 1.f : -1.f), 0.f);
      EXPECT_EQ(p.y_mm, ball_y > 0 ? -f.width_mm / 2 : f.width_mm / 2);
      EXPECT_TRUE(field.inside_lines(p.x_mm, p.y_mm));
      EXPECT_NEAR(std::sin(p.theta_rad), p.y_mm < 0 ? 1.f : -1.f, 1e-6f);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothFields, Positions, ::testing::Values("spl2011", "spl2020"));

// --- manual placement at SET -----------------------------------------------------------

TEST_F(RefereeTest, RobotsNotInALegalPositionAtSetArePlaced) {
  put_robot({0, 3}, 500.f, 0.f, 0.f);    // in the opponents' half
  put_robot({1, 2}, 300.f, 0.f, kPi);    // defending, inside the centre circle
  put_robot({0, 2}, -300.f, 0.f, 0.f);   // kicking off: may stand in the circle
  put_robot({1, 4}, 1500.f, -800.f, kPi); // legal
  put_robot({0, 4}, -2700.f, 300.f, 0.f); // field player in its goal box
  update_at(0);
  EXPECT_TRUE(update_at(45.9).placements.empty()); // READY: they walk themselves
  const auto d = update_at(46);                   // SET: team 0 kicks off
  ASSERT_EQ(d.placements.size(), 3u);
  EXPECT_EQ(d.placements[0].robot, (RobotId{0, 3}));
  expect_pose(d.placements[0].pose, -1500.f, 800.f, 0.f);
  EXPECT_EQ(d.placements[1].robot, (RobotId{0, 4}));
  expect_pose(d.placements[1].pose, -1500.f, -800.f, 0.f);
  EXPECT_EQ(d.placements[2].robot, (RobotId{1, 2}));
  expect_pose(d.placements[2].pose, 850.f, 0.f, kPi);
}

TEST_F(RefereeTest, ManualPlacementCanBeSwitchedOff) {
  rules.manual_placement = false;
  put_robot({0, 3}, 500.f, 0.f, 0.f);
  update_at(0);
  EXPECT_TRUE(update_at(46).placements.empty());
}

} // namespace
} // namespace touchline::sim
