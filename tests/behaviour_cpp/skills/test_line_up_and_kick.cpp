// LineUpAndKick: approach, line up the foot, kick when aligned; the same cases as
// tests/behaviour_py/test_line_up_and_kick.py.
#include "touchline/behaviour/skills/line_up_and_kick.hpp"

#include <gtest/gtest.h>

#include "boards.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;
using touchline::behaviour::test::relative;
using ActionCommand::ActionType;
using ActionCommand::Foot;

namespace {

void expectVelocities(const ActionCommand::All& command, float forward, float left, float turn) {
  EXPECT_NEAR(command.body.forward, forward, 1e-3f);
  EXPECT_NEAR(command.body.left, left, 1e-3f);
  EXPECT_NEAR(command.body.turn, turn, 1e-3f);
}

Blackboard ballAt(float x, float y, bool seen = true, int lost = 0) { return board({0, 0, 0}, x, y, seen, lost); }

} // namespace

TEST(LineUpAndKickSkill, BallInFrontOfTheLeftFootKicksLeft) {
  LineUpAndKick skill;
  const auto body = skill.tick(ballAt(130.f, 50.f)).body;
  EXPECT_EQ(body.actionType, ActionType::KICK);
  EXPECT_EQ(body.foot, Foot::LEFT);
  EXPECT_FLOAT_EQ(body.power, 1.f);
  EXPECT_TRUE(skill.liningUp());
}

TEST(LineUpAndKickSkill, BallInFrontOfTheRightFootKicksRight) {
  const auto body = LineUpAndKick().tick(ballAt(130.f, -50.f)).body;
  EXPECT_EQ(body.actionType, ActionType::KICK);
  EXPECT_EQ(body.foot, Foot::RIGHT);
}

TEST(LineUpAndKickSkill, NotFacingTheGoalTurnsInsteadOfKicking) {
  const AbsCoord pos{0.f, 0.f, 0.3f}; // ball in front of the left foot, goal 0.33 rad to the right
  const auto [x, y] = relative(pos, 130.f, 50.f);
  const auto command = LineUpAndKick().tick(board(pos, x, y));
  EXPECT_EQ(command.body.actionType, ActionType::WALK);
  expectVelocities(command, 0.f, 0.f, -0.5f);
}

TEST(LineUpAndKickSkill, BallTooFarTakesSmallSteps) {
  const auto command = LineUpAndKick().tick(ballAt(250.f, 40.f));
  EXPECT_EQ(command.body.actionType, ActionType::WALK);
  expectVelocities(command, 100.f, -20.f, -0.02909f);
}

TEST(LineUpAndKickSkill, FootIsKeptWhileLiningUp) {
  LineUpAndKick skill;
  skill.tick(ballAt(250.f, 40.f));
  EXPECT_EQ(skill.foot(), Foot::LEFT);
  const auto command = skill.tick(ballAt(130.f, -10.f)); // now right of centre: left foot still
  EXPECT_EQ(skill.foot(), Foot::LEFT);
  expectVelocities(command, 0.f, -100.f, 0.00697f);
  LineUpAndKick fresh;
  const auto freshCommand = fresh.tick(ballAt(130.f, -10.f));
  EXPECT_EQ(fresh.foot(), Foot::RIGHT);
  expectVelocities(freshCommand, 0.f, 80.f, 0.00697f);
}

TEST(LineUpAndKickSkill, FarBallApproachesLikeGoToBall) {
  const Blackboard blackboard = ballAt(1000.f, 300.f);
  LineUpAndKick skill;
  const auto body = skill.tick(blackboard).body;
  const auto expected = GoToBall().tick(blackboard).body;
  EXPECT_EQ(body.forward, expected.forward);
  EXPECT_EQ(body.left, expected.left);
  EXPECT_EQ(body.turn, expected.turn);
  EXPECT_FALSE(skill.liningUp());
}

TEST(LineUpAndKickSkill, LiningUpEndsWhenTheBallGoes) {
  LineUpAndKick skill;
  skill.tick(ballAt(250.f, 40.f));
  skill.tick(ballAt(450.f, 0.f)); // within the leave distance
  EXPECT_TRUE(skill.liningUp());
  skill.tick(ballAt(600.f, 0.f));
  EXPECT_FALSE(skill.liningUp());
}

TEST(LineUpAndKickSkill, LostBallStands) {
  LineUpAndKick skill;
  skill.tick(ballAt(250.f, 40.f));
  EXPECT_EQ(skill.tick(ballAt(250.f, 40.f, false, BALL_LOST_FRAMES + 1)).body.actionType, ActionType::STAND);
  EXPECT_FALSE(skill.liningUp());
}

TEST(LineUpAndKickSkill, DribbleVariantAndPower) {
  auto body = LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, true).tick(ballAt(130.f, 50.f)).body;
  EXPECT_EQ(body.actionType, ActionType::DRIBBLE);
  EXPECT_FLOAT_EQ(body.power, 1.f);
  body = LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, false, 0.7f).tick(ballAt(130.f, 50.f)).body;
  EXPECT_EQ(body.actionType, ActionType::KICK);
  EXPECT_FLOAT_EQ(body.power, 0.7f);
}
