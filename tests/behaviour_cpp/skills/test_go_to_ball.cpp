// GoToBall: behind the ball facing the goal, via GoToPose; the same cases as
// tests/behaviour_py/test_go_to_ball.py.
#include "touchline/behaviour/skills/go_to_ball.hpp"

#include <gtest/gtest.h>

#include "boards.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;

namespace {
void expectPose(const AbsCoord& pose, float x, float y, float theta) {
  EXPECT_NEAR(pose.x, x, 1e-3f);
  EXPECT_NEAR(pose.y, y, 1e-3f);
  EXPECT_NEAR(pose.theta, theta, 1e-5f);
}
} // namespace

TEST(GoToBallSkill, PointBehindBallOnTheLineFromTheGoal) {
  expectPose(pointBehindBall({1000.f, 0.f, 0.f}, 3000.f, 0.f, 200.f), 800.f, 0.f, 0.f);
  expectPose(pointBehindBall({2000.f, 1000.f, 0.f}, 3000.f, 0.f, 200.f), 1858.5786f, 1141.4214f, -kPi / 4);
  expectPose(pointBehindBall({0.f, 0.f, 0.f}, -3000.f, 0.f, 200.f), 200.f, 0.f, kPi);
}

TEST(GoToBallSkill, PointBehindBallAtTheGoalAimsAlongX) {
  expectPose(pointBehindBall({3000.f, 0.f, 0.f}, 3000.f, 0.f, 200.f), 2800.f, 0.f, 0.f);
}

TEST(GoToBallSkill, WalksToTheBall) {
  const auto command = GoToBall().tick(board({0, 0, 0}, 1000.f, 0.f));
  EXPECT_EQ(command.body.actionType, ActionCommand::ActionType::WALK);
  EXPECT_NEAR(command.body.forward, 300.f, 1e-3f);
  EXPECT_NEAR(command.body.turn, 0.f, 1e-5f);
}

TEST(GoToBallSkill, StandsBehindTheBallFacingTheGoal) {
  GoToBall skill;
  EXPECT_EQ(skill.tick(board({800.f, 0.f, 0.f}, 1000.f, 0.f)).body.actionType, ActionCommand::ActionType::STAND);
  EXPECT_TRUE(skill.goToPose().arrived());
}

TEST(GoToBallSkill, GoalIsAParameter) {
  // Kicking towards our own half: behind the ball is on its +x side, facing -x.
  GoToBall skill(-3000.f);
  EXPECT_EQ(skill.tick(board({200.f, 0.f, kPi}, 0.f, 0.f)).body.actionType, ActionCommand::ActionType::STAND);
}

TEST(GoToBallSkill, LostBallStands) {
  EXPECT_EQ(GoToBall().tick(board({0, 0, 0}, 1000.f, 0.f, false, BALL_LOST_FRAMES + 1)).body.actionType,
            ActionCommand::ActionType::STAND);
  EXPECT_EQ(GoToBall().tick(board({0, 0, 0}, 1000.f, 0.f, false, BALL_LOST_FRAMES)).body.actionType,
            ActionCommand::ActionType::WALK); // still recent
}
