#include "touchline/behaviour/walk_skills.hpp"

#include <gtest/gtest.h>

using namespace touchline::api;
using touchline::behaviour::GoToPose;

namespace {
Blackboard at(float x, float y, float theta) {
  Blackboard blackboard;
  blackboard.localisation.robotPos = {x, y, theta};
  return blackboard;
}
} // namespace

TEST(GoToPose, FarTargetBehindTurnsOnTheSpotFirst) {
  GoToPose skill({-2000, 0, 0});
  const auto all = skill.tick(at(0, 0, 0)); // target straight behind
  EXPECT_EQ(all.body.actionType, ActionCommand::ActionType::WALK);
  EXPECT_EQ(all.body.forward, 0.f);
  EXPECT_NE(all.body.turn, 0.f);
}

TEST(GoToPose, FarTargetAheadWalksForwardFullSpeed) {
  GoToPose skill({2000, 0, 0});
  const auto all = skill.tick(at(0, 0, 0));
  EXPECT_FLOAT_EQ(all.body.forward, 300.f);
  EXPECT_NEAR(all.body.turn, 0.f, 1e-6f);
}

TEST(GoToPose, FarTargetToTheLeftTurnsLeft) {
  GoToPose skill({1000, 1000, 0});
  EXPECT_GT(skill.tick(at(0, 0, 0)).body.turn, 0.f);
  EXPECT_LT(skill.tick(at(0, 0, 1.5f)).body.turn, 0.f); // overshot: turn back right
}

TEST(GoToPose, NearTargetSideStepsAndAlignsHeading) {
  GoToPose skill({0, 100, 0.5f});
  const auto all = skill.tick(at(0, 0, 0));
  EXPECT_GT(all.body.left, 0.f);
  EXPECT_NEAR(all.body.forward, 0.f, 1e-3f);
  EXPECT_GT(all.body.turn, 0.f);
}

TEST(GoToPose, ArrivedStandsUntilPushedAway) {
  GoToPose skill({500, 500, 1.f});
  EXPECT_EQ(skill.tick(at(510, 495, 1.02f)).body.actionType, ActionCommand::ActionType::STAND);
  EXPECT_TRUE(skill.arrived());
  EXPECT_EQ(skill.tick(at(600, 500, 1.f)).body.actionType, ActionCommand::ActionType::STAND); // within hysteresis
  EXPECT_EQ(skill.tick(at(800, 500, 1.f)).body.actionType, ActionCommand::ActionType::WALK);
  EXPECT_FALSE(skill.arrived());
}
