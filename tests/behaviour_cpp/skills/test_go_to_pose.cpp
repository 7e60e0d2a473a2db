// GoToPose: forward-first, then thesis Algorithm 4.3; the same cases as
// tests/behaviour_py/test_go_to_pose.py.
#include "touchline/behaviour/skills/go_to_pose.hpp"

#include <gtest/gtest.h>

#include "boards.hpp"

using namespace touchline::api;
using touchline::behaviour::skills::FIELD_EDGE_SLACK;
using touchline::behaviour::skills::forwardFirstSpeedScale;
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

TEST(GoToPoseSkill, TargetFarBehindIsWalkedBackwardsWhenTheRobotMustEndFacingAway) {
  // Backwards at 200 mm/s: 10 s; turning round, 300 mm/s forward and turning back: 10.9 s.
  GoToPose skill(-2000.f, -100.f, 0.f);
  const auto command = skill.tick(board({0, 0, 0}));
  EXPECT_EQ(command.body.actionType, ActionCommand::ActionType::WALK);
  expectVelocities(command, -200.f, -10.f, 0.f);
  EXPECT_TRUE(skill.near());
}

TEST(GoToPoseSkill, FarTargetAheadWalksForwardAtFullSpeedSteering) {
  // Ahead, both ways take as long: forward-first (Algorithm 4.3 only when 0.25 s faster),
  // 0.05 rad off: cos^2 of it, 99.75 % of full speed.
  expectVelocities(GoToPose(2000.f, 100.f, 0.f).tick(board({0, 0, 0})), 299.2519f, 0.f, 0.09992f, 1e-3f);
}

TEST(GoToPoseSkill, ForwardFirstWalksSlowerTheFurtherTheTargetIsOffItsHeading) {
  EXPECT_EQ(forwardFirstSpeedScale(0.f), 1.f);
  EXPECT_NEAR(forwardFirstSpeedScale(radians(45)), 0.5f, 1e-6f);
  EXPECT_NEAR(forwardFirstSpeedScale(radians(-60)), 0.25f, 1e-6f);
  EXPECT_EQ(forwardFirstSpeedScale(radians(100)), 0.f);
  // 2 m at 45 degrees, ending facing there: walks at half speed while turning at full rate.
  const AbsCoord target = at(2000.f, radians(45));
  expectVelocities(GoToPose(target.x, target.y, radians(45)).tick(board({0, 0, 0})), 150.f, 0.f, 1.5f);
}

TEST(GoToPoseSkill, ForwardFirstWhereItIsFaster) {
  // 2 m at 80 degrees, ending facing +x: sideways 9.9 s; turn, walk forward, turn back 8.5 s.
  // It turns at full rate, walking on at cos^2(80 degrees) = 3 % of full speed.
  const AbsCoord target = at(2000.f, radians(80));
  GoToPose skill(target.x, target.y, 0.f);
  expectVelocities(skill.tick(board({0, 0, 0})), 9.0459f, 0.f, 1.5f);
  EXPECT_FALSE(skill.near());
}

TEST(GoToPoseSkill, Algorithm43WithinTheThreshold) {
  const AbsCoord target = at(390.f, radians(20)); // same bearing, inside: step there diagonally
  GoToPose skill(target.x, target.y, 0.f);
  expectVelocities(skill.tick(board({0, 0, 0})), 300.f, 109.1911f, 0.f);
  EXPECT_TRUE(skill.near());
}

TEST(GoToPoseSkill, Algorithm43UntilForwardFirstIsClearlyFaster) {
  // A target to the left, ending facing +x: sideways takes d/200 s, turning twice and forward
  // 2.09 s + d/300: Algorithm 4.3 is 0.25 s faster under 1107 mm, and kept until 0.5 s slower (1557 mm).
  GoToPose skill(0.f, 0.f, 0.f);
  skill.tick(board({0.f, -390.f, 0.f}));
  EXPECT_TRUE(skill.near());
  skill.tick(board({0.f, -1400.f, 0.f})); // 0.24 s slower: still Algorithm 4.3
  EXPECT_TRUE(skill.near());
  const auto command = skill.tick(board({0.f, -1600.f, 0.f})); // 0.57 s slower: forward-first
  EXPECT_FALSE(skill.near());
  EXPECT_NEAR(command.body.forward, 0.f, 1e-6f); // at 90 degrees
  EXPECT_GT(command.body.turn, 0.f);
  GoToPose fresh(0.f, 0.f, 0.f);
  fresh.tick(board({0.f, -1400.f, 0.f}));
  EXPECT_FALSE(fresh.near());
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

TEST(GoToPoseSkill, ATargetOffTheFieldIsWalkedToOnlyJustBeyondTheLine) {
  // Behind a ball on the touchline the target lies out; the referee penalises 200 mm out.
  GoToPose beside(0.f, 2300.f, 0.f);
  EXPECT_EQ(beside.tick(board({0.f, 2000.f + FIELD_EDGE_SLACK, 0.f})).body.actionType, ActionCommand::ActionType::STAND);
  GoToPose behind(3400.f, -100.f, 0.f);
  EXPECT_EQ(behind.tick(board({3000.f + FIELD_EDGE_SLACK, -100.f, 0.f})).body.actionType,
            ActionCommand::ActionType::STAND);
}
