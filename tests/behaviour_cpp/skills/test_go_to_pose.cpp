// GoToPose: forward-first, then thesis Algorithm 4.3; the same cases as
// tests/behaviour_py/test_go_to_pose.py.
#include "touchline/behaviour/skills/go_to_pose.hpp"

#include <gtest/gtest.h>

#include "boards.hpp"

using namespace touchline::api;
using touchline::behaviour::skills::GoToPose;
using touchline::behaviour::test::board;
using touchline::behaviour::test::radians;

namespace {

void expectVelocities(const ActionCommand::All& command, float forward, float left, float turn, float tolerance = 1e-3f) {
  EXPECT_NEAR(command.body.forward, forward, tolerance);
  EXPECT_NEAR(command.body.left, left, tolerance);
  EXPECT_NEAR(command.body.turn, turn, tolerance);
}

AbsCoord at(float distance, float bearing) { return {distance * std::cos(bearing), distance * std::sin(bearing), 0.f}; }

} // namespace

TEST(GoToPoseSkill, TargetBehindTurnsOnTheSpotFirst) {
  const auto command = GoToPose(-2000.f, -100.f, 0.f).tick(board({0, 0, 0}));
  EXPECT_EQ(command.body.actionType, ActionCommand::ActionType::WALK);
  expectVelocities(command, 0.f, 0.f, -1.5f);
}

TEST(GoToPoseSkill, FarTargetAheadWalksForwardAtFullSpeedSteering) {
  expectVelocities(GoToPose(2000.f, 100.f, 0.f).tick(board({0, 0, 0})), 300.f, 0.f, 0.09992f, 1e-4f);
}

TEST(GoToPoseSkill, ForwardFirstBeyondTheThreshold) {
  const AbsCoord target = at(410.f, radians(20)); // 20 degrees off: face it first
  expectVelocities(GoToPose(target.x, target.y, 0.f).tick(board({0, 0, 0})), 0.f, 0.f, 0.69813f, 1e-4f);
}

TEST(GoToPoseSkill, Algorithm43WithinTheThreshold) {
  const AbsCoord target = at(390.f, radians(20)); // same bearing, inside: step there diagonally
  GoToPose skill(target.x, target.y, 0.f);
  expectVelocities(skill.tick(board({0, 0, 0})), 300.f, 109.1911f, 0.f);
  EXPECT_TRUE(skill.near());
}

TEST(GoToPoseSkill, NearUntilBeyondTheLeaveDistance) {
  GoToPose skill(0.f, 0.f, 0.f);
  skill.tick(board({-390.f, 0.f, 0.f}));
  EXPECT_TRUE(skill.near());
  skill.tick(board({-450.f, -100.f, 0.f})); // 461 mm: still Algorithm 4.3
  EXPECT_TRUE(skill.near());
  const auto command = skill.tick(board({-500.f, -200.f, 0.f})); // 539 mm, 22 degrees off: forward-first again
  EXPECT_FALSE(skill.near());
  EXPECT_EQ(command.body.forward, 0.f);
  EXPECT_GT(command.body.turn, 0.f);
}

TEST(GoToPoseSkill, Algorithm43WorkedExampleClamped) {
  // Robot (1000, 500, 0.3), target (1200, 700): fwd = 250.171, lft = -131.963 (4.3's
  // runswift angles); x2 gain -> (500.34, 263.93), scaled by 300/500.34 into the limits.
  expectVelocities(GoToPose(1200.f, 700.f, 0.4f).tick(board({1000.f, 500.f, 0.3f})), 300.f, 158.2475f, 0.2f);
}

TEST(GoToPoseSkill, Algorithm43WorkedExampleUnclamped) {
  // Target (1050, 480): fwd = 41.8564, lft = 33.8827 -> x2 gain.
  expectVelocities(GoToPose(1050.f, 480.f, 0.35f).tick(board({1000.f, 500.f, 0.3f})), 83.7128f, -67.7655f, 0.1f);
}

TEST(GoToPoseSkill, NearButHeadingOffTurnsOnTheSpot) {
  expectVelocities(GoToPose(100.f, 0.f, 1.f).tick(board({0, 0, 0})), 0.f, 0.f, 1.5f);
}

TEST(GoToPoseSkill, ArrivedStandsUntilPushedOrTurnedAway) {
  using ActionCommand::ActionType;
  GoToPose skill(500.f, 500.f, 1.f);
  EXPECT_EQ(skill.tick(board({510.f, 495.f, 1.02f})).body.actionType, ActionType::STAND);
  EXPECT_TRUE(skill.arrived());
  EXPECT_EQ(skill.tick(board({600.f, 500.f, 1.f})).body.actionType, ActionType::STAND); // 100 mm: within hysteresis
  EXPECT_EQ(skill.tick(board({500.f, 500.f, 1.3f})).body.actionType, ActionType::STAND); // 0.3 rad: within hysteresis
  EXPECT_EQ(skill.tick(board({500.f, 500.f, 1.4f})).body.actionType, ActionType::WALK);  // 0.4 rad: left
  EXPECT_FALSE(skill.arrived());
  EXPECT_EQ(skill.tick(board({600.f, 500.f, 1.f})).body.actionType, ActionType::WALK); // 100 mm: not yet arrived again
}

TEST(GoToPoseSkill, FaceBallTurnsToTheBallNotTheta) {
  GoToPose skill(0.f, 0.f, 0.f, true);
  expectVelocities(skill.tick(board({0, 0, 0}, 0.f, 1000.f)), 0.f, 0.f, 1.5f);
  EXPECT_EQ(skill.tick(board({0, 0, kPi / 2}, 0.f, 1000.f)).body.actionType, ActionCommand::ActionType::STAND);
}
