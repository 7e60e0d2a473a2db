// GoToBall: behind the ball facing the goal, via GoToPose; the same cases as
// tests/behaviour_py/test_go_to_ball.py.
#include "touchline/behaviour/skills/go_to_ball.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "boards.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/field.hpp"

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

TEST(GoToBallSkill, InTheOpenTheAimIsTheGoal) {
  const FieldPointExact open = kickAim(1000.0, 500.0, 3000.0, 0.0, 200.0);
  EXPECT_EQ(open.x, 3000.0);
  EXPECT_EQ(open.y, 0.0);
  const FieldPointExact nearLine = kickAim(0.0, 1900.0, 3000.0, 0.0, 200.0); // behind it is still on the field
  EXPECT_EQ(nearLine.x, 3000.0);
  EXPECT_EQ(nearLine.y, 0.0);
}

TEST(GoToBallSkill, NearAGoalLineTheAimMovesInProportionToTheMouthsNearestPoint) {
  const FieldPointExact far = goalMouthAim(3000.0 - GOAL_MOUTH_AIM_DIST, -585.0, 3000.0, 0.0);
  EXPECT_EQ(far.x, 3000.0);
  EXPECT_EQ(far.y, 0.0);
  const FieldPointExact halfway = goalMouthAim(3000.0 - GOAL_MOUTH_AIM_DIST / 2, -585.0, 3000.0, 0.0);
  EXPECT_DOUBLE_EQ(halfway.x, 3000.0 + GOAL_MOUTH_AIM_DEPTH / 2);
  EXPECT_DOUBLE_EQ(halfway.y, -585.0 / 2);
  const FieldPointExact besideTheMouth = goalMouthAim(-3000.0, 1500.0, -3000.0, 0.0); // the other goal too
  EXPECT_DOUBLE_EQ(besideTheMouth.x, -3000.0 - GOAL_MOUTH_AIM_DEPTH);
  EXPECT_DOUBLE_EQ(besideTheMouth.y, GOAL_MOUTH_HALF_WIDTH);
  const FieldPointExact pass = kickAim(900.0, 400.0, 1000.0, 500.0, 200.0); // not a goal: as given
  EXPECT_EQ(pass.x, 1000.0);
  EXPECT_EQ(pass.y, 500.0);
}

namespace {
/// Where a robot stands behind the ball at (ballX, ballY) aiming at kickAim's point.
AbsCoord standing(float ballX, float ballY) {
  const FieldPointExact aim = kickAim(ballX, ballY, 3000.0, 0.0, 200.0);
  return pointBehindBall({ballX, ballY, 0.f}, static_cast<float>(aim.x), static_cast<float>(aim.y), 200.f);
}
} // namespace

TEST(GoToBallSkill, ABallOnATouchlineIsAimedAlongItFromNoFurtherOutThanTheSlack) {
  // Facing the goal from behind a ball on the touchline would stand the robot 141 mm
  // beyond it; the aim turns towards the line until the robot stands FIELD_EDGE_SLACK out.
  const AbsCoord left = standing(1000.f, FIELD_HALF_WIDTH);
  EXPECT_NEAR(left.y, FIELD_HALF_WIDTH + FIELD_EDGE_SLACK, 1e-2f);
  EXPECT_GT(left.theta, -kPi / 4); // between the goal's heading and the line's, inwards
  EXPECT_LT(left.theta, 0.f);
  const AbsCoord right = standing(1000.f, -FIELD_HALF_WIDTH);
  EXPECT_NEAR(right.y, -FIELD_HALF_WIDTH - FIELD_EDGE_SLACK, 1e-2f);
  EXPECT_GT(right.theta, 0.f);
  EXPECT_LT(right.theta, kPi / 4);
}

TEST(GoToBallSkill, ABallInTheMouthOnTheGoalLineIsAimedIntoTheGoalFromClearOfThePost) {
  // Aimed at the goal's centre, along the line, the spot behind it was at the post (3000,
  // -700): the striker stood against the post for 28 s until the referee restarted the game.
  const AbsCoord stand = standing(FIELD_HALF_LENGTH - 10.f, -585.f);
  EXPECT_LT(std::abs(stand.theta), 0.25f); // into the goal
  // clear of the post by more than its radius (50) and a foot's reach (its corner 124 mm out)
  EXPECT_GT(std::hypot(stand.x - FIELD_HALF_LENGTH, stand.y + 700.f), 200.f);
  EXPECT_LT(stand.x, FIELD_HALF_LENGTH); // on the field
}

TEST(GoToBallSkill, ABallOnTheOwnGoalLineIsAimedOutToItsGoalSide) {
  const AbsCoord stand = standing(-FIELD_HALF_LENGTH, 500.f);
  EXPECT_NEAR(stand.x, -FIELD_HALF_LENGTH - FIELD_EDGE_SLACK, 1e-2f);
  EXPECT_GT(stand.theta, -kPi / 2); // along the line, towards the goal's side (-y)
  EXPECT_LT(stand.theta, -kPi / 4);
}

TEST(GoToBallSkill, ABallInACornerIsAimedOutOfItStandingAsFarBeyondBothLines) {
  // Turning off the goal line stood the robot beyond the touchline again, facing along the
  // goal line with the ball beside it: 10 s stuck in the own corner.
  for (const auto [ballX, ballY] : {std::pair{-FIELD_HALF_LENGTH + 10.f, -FIELD_HALF_WIDTH + 30.f},
                                    std::pair{-FIELD_HALF_LENGTH, FIELD_HALF_WIDTH}}) {
    const AbsCoord stand = standing(ballX, ballY);
    EXPECT_NEAR(-stand.x - FIELD_HALF_LENGTH, std::abs(stand.y) - FIELD_HALF_WIDTH, 1e-2f);
    EXPECT_GT(std::abs(stand.y), FIELD_HALF_WIDTH + FIELD_EDGE_SLACK); // no aim keeps it within both
    const float inwards = ballY < 0.f ? stand.theta : -stand.theta; // out of the corner, into the field
    EXPECT_GT(inwards, 0.f);
    EXPECT_LT(inwards, kPi / 2);
  }
}

TEST(GoToBallSkill, TheCornerAimMeetsTheOneLineAimWhereTheCornerStarts) {
  // 120 mm and 160 mm of room to the lines' slack: aiming (0.6, 0.8), the robot stands on both.
  const float ballX = -(FIELD_HALF_LENGTH + FIELD_EDGE_SLACK - 120.f);
  const float ballY = -(FIELD_HALF_WIDTH + FIELD_EDGE_SLACK - 160.f);
  const FieldPointExact aim = cornerAim(ballX, ballY, 200.0);
  EXPECT_NEAR(aim.x, 0.6, 1e-9);
  EXPECT_NEAR(aim.y, 0.8, 1e-9);
  const AbsCoord stand = standing(ballX, ballY);
  EXPECT_NEAR(stand.x, -FIELD_HALF_LENGTH - FIELD_EDGE_SLACK, 1e-2f);
  EXPECT_NEAR(stand.y, -FIELD_HALF_WIDTH - FIELD_EDGE_SLACK, 1e-2f);
}

TEST(GoToBallSkill, BesideABallOnTheTouchlineItStandsFacingAlongTheLine) {
  // Where it was: 100 mm short of a target out of its reach, the ball beside it, never lined up.
  GoToBall skill;
  EXPECT_EQ(skill.tick(board(standing(1000.f, FIELD_HALF_WIDTH), 1000.f, FIELD_HALF_WIDTH)).body.actionType,
            ActionCommand::ActionType::STAND);
  EXPECT_TRUE(skill.goToPose().arrived());
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
