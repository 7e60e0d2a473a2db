// LineUpAndKick: approach, line up the foot, kick when aligned; the same cases as
// tests/behaviour_py/test_line_up_and_kick.py.
#include "touchline/behaviour/skills/line_up_and_kick.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "boards.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;
using touchline::behaviour::test::relative;
using touchline::behaviour::test::seenRobot;
using ActionCommand::ActionType;
using ActionCommand::Foot;

namespace {

void expectVelocities(const ActionCommand::All& command, float forward, float left, float turn) {
  EXPECT_NEAR(command.body.forward, forward, 1e-3f);
  EXPECT_NEAR(command.body.left, left, 1e-3f);
  EXPECT_NEAR(command.body.turn, turn, 1e-3f);
}

Blackboard ballAt(float x, float y, bool seen = true, int lost = 0) { return board({0, 0, 0}, x, y, seen, lost); }

/// LineUpAndKick at the opponent goal with carry on (Striker's).
LineUpAndKick carrier() { return LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, false, std::nullopt, std::nullopt, true); }

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
  const AbsCoord pos{1500.f, 0.f, 0.3f}; // ball in front of the left foot, goal 0.36 rad to the right
  const auto [x, y] = relative(pos, 130.f, 50.f);
  const auto command = LineUpAndKick().tick(board(pos, x, y));
  EXPECT_EQ(command.body.actionType, ActionType::WALK);
  expectVelocities(command, 0.f, 0.f, -0.72380f); // TURN_GAIN x the 0.36 rad to the goal
}

TEST(LineUpAndKickSkill, LiningUpNeverStepsIntoARobotItTouches) {
  // Lining up, the ball ahead and to the left: a step forward and left, unless a robot
  // against the left arm is there; then forward and right (avoid.hpp's keepOffTouches).
  const auto free = LineUpAndKick().tick(ballAt(250.f, 150.f)).body;
  EXPECT_EQ(free.actionType, ActionType::WALK);
  EXPECT_GT(free.forward, 0.f);
  EXPECT_GT(free.left, 0.f);
  Blackboard touching = ballAt(250.f, 150.f);
  touching.motion.touchLeft = true;
  const auto touched = LineUpAndKick().tick(touching).body;
  EXPECT_EQ(touched.actionType, ActionType::WALK);
  EXPECT_GT(touched.forward, 0.f);
  EXPECT_LT(touched.left, 0.f);
}

TEST(LineUpAndKickSkill, LiningUpNeverStepsIntoTheOwnGoalBox) {
  // Lining up with the ball short of the kicking spot and to the left: a step back and
  // left; in front of the own goal box, where a field player is an illegal defender, the
  // step back is dropped (avoid.hpp's keepOutOfOwnBox, through keepClear).
  const auto step = [](AbsCoord pos) {
    const auto [x, y] = relative(pos, 60.f, 120.f);
    Blackboard blackboard = board(pos, x, y);
    blackboard.gameController.playerNumber = 2; // a field player: the goalie may enter
    return LineUpAndKick().tick(blackboard).body;
  };
  const auto open = step({0.f, 0.f, 0.f});
  EXPECT_EQ(open.actionType, ActionType::WALK);
  EXPECT_LT(open.forward, 0.f);
  EXPECT_GT(open.left, 0.f);
  const auto byTheBox = step({OWN_BOX_FRONT_X + 150.f, 0.f, 0.f});
  EXPECT_EQ(byTheBox.actionType, ActionType::WALK);
  EXPECT_GE(byTheBox.forward, 0.f);
  EXPECT_GT(byTheBox.left, 0.f);
}

TEST(LineUpAndKickSkill, FarFromTheGoalAKickOffItsLineIsTaken) {
  const AbsCoord pos{0.f, 0.f, 0.3f}; // the goal 3 km away, 0.33 rad to the right
  const auto [x, y] = relative(pos, 130.f, 50.f);
  const auto body = LineUpAndKick().tick(board(pos, x, y)).body;
  EXPECT_EQ(body.actionType, ActionType::KICK);
  EXPECT_EQ(body.foot, Foot::LEFT);
}

TEST(LineUpAndKickSkill, ABallOnTheTouchlineIsKickedAlongIt) {
  // The goal 1.1 rad to the right: facing it, the robot would stand beyond the line. Facing
  // along the line (turned inwards as far as the slack lets it stand out) it kicks.
  const float theta = std::asin((FIELD_HALF_WIDTH - (FIELD_HALF_WIDTH + FIELD_EDGE_SLACK)) / BEHIND_BALL_DIST);
  const float ballX = 2000.f, ballY = FIELD_HALF_WIDTH;
  const AbsCoord pos{ballX - 130.f * std::cos(theta) + 50.f * std::sin(theta),
                     ballY - 130.f * std::sin(theta) - 50.f * std::cos(theta), theta};
  const auto [x, y] = relative(pos, 130.f, 50.f);
  EXPECT_NEAR(x, ballX, 1e-2f);
  EXPECT_NEAR(y, ballY, 1e-2f);
  const auto body = LineUpAndKick().tick(board(pos, ballX, ballY)).body;
  EXPECT_EQ(body.actionType, ActionType::KICK);
  EXPECT_EQ(body.foot, Foot::LEFT);
}

TEST(LineUpAndKickSkill, ABallInTheOwnCornerIsLinedUpFromWhereTheApproachEnds) {
  // The approach's target, behind the ball, lies beyond both lines; the walk stops at the
  // slack. From there the ball must be ahead and the aim in line, or nobody kicks it.
  const AbsCoord ball{-FIELD_HALF_LENGTH + 20.f, -FIELD_HALF_WIDTH + 20.f, 0.f};
  const FieldPointExact aim = kickAim(ball.x, ball.y, 3000.0, 0.0, BEHIND_BALL_DIST);
  const AbsCoord target =
      pointBehindBall(ball, static_cast<float>(aim.x), static_cast<float>(aim.y), BEHIND_BALL_DIST);
  const FieldPoint reached = clampToField(target.x, target.y, -FIELD_EDGE_SLACK);
  LineUpAndKick skill;
  EXPECT_EQ(skill.tick(board({reached.x, reached.y, target.theta}, ball.x, ball.y)).body.actionType, ActionType::WALK);
  EXPECT_TRUE(skill.liningUp());
}

namespace {

// The goal 1.04 rad to the right, the ball 38 mm beyond the kicking spot and 38 mm off the
// left foot's line (within a kick's tolerances): an approach alone, a kick at once when a
// robot is near the ball.
Blackboard contestBoard(float ballX = 168.f, float ballY = 88.f) {
  const AbsCoord pos{1500.f, 0.f, 0.9f};
  const auto [x, y] = relative(pos, ballX, ballY);
  return board(pos, x, y);
}

} // namespace

TEST(LineUpAndKickSkill, AContestedBallIsKickedAtOnceWhereverItGainsGround) {
  Blackboard blackboard = contestBoard();
  LineUpAndKick alone;
  const auto turning = alone.tick(blackboard).body;
  EXPECT_EQ(turning.actionType, ActionType::WALK);
  EXPECT_LT(turning.turn, 0.f); // turns to the goal, on its right, before kicking
  blackboard.vision.robots = {seenRobot(1200.f, 0.f)}; // over 500 mm from the ball
  EXPECT_EQ(LineUpAndKick().tick(blackboard).body.actionType, ActionType::WALK);
  blackboard.vision.robots = {seenRobot(450.f, 120.f)}; // across the ball
  LineUpAndKick contested;
  const auto body = contested.tick(blackboard).body;
  EXPECT_TRUE(contested.contested());
  EXPECT_EQ(body.actionType, ActionType::KICK);
  EXPECT_EQ(body.foot, Foot::LEFT);
}

TEST(LineUpAndKickSkill, AContestedKickWaitsForTheBallWithinTheSwingsReach) {
  // 60 mm beyond the kicking spot the swing (to 200 mm ahead) meets the ball at its end, and
  // 50 mm off the foot's line with the foot's edge: a step closer first.
  for (const auto [ballX, ballY] : {std::pair{190.f, 88.f}, std::pair{168.f, 100.f}}) {
    Blackboard blackboard = contestBoard(ballX, ballY);
    blackboard.vision.robots = {seenRobot(450.f, 120.f)};
    LineUpAndKick contested;
    EXPECT_EQ(contested.tick(blackboard).body.actionType, ActionType::WALK) << ballX << ", " << ballY;
    EXPECT_TRUE(contested.contested());
  }
}

TEST(LineUpAndKickSkill, AStalledContestStepsRoundTheBallAwayFromTheRobotThenKicksAgain) {
  Blackboard blackboard = contestBoard();
  blackboard.vision.robots = {seenRobot(450.f, 120.f)}; // left of the ball: step right
  LineUpAndKick skill;
  for (int frame = 0; frame < 1 + STALL_FRAMES; ++frame) // kicks, and the ball stays
    EXPECT_EQ(skill.tick(blackboard).body.actionType, ActionType::KICK) << frame;
  for (int frame = 0; frame < SIDESTEP_FRAMES; ++frame) {
    const auto command = skill.tick(blackboard);
    EXPECT_EQ(command.body.actionType, ActionType::WALK) << frame;
    expectVelocities(command, 0.f, -LINE_UP_MAX_SPEED, 0.96503f); // turning to the ball, TURN_GAIN x its bearing
  }
  EXPECT_EQ(skill.tick(blackboard).body.actionType, ActionType::KICK); // then kicks again from there
}

TEST(LineUpAndKickSkill, AContestedBallThatMovesStartsTheStallCountAgain) {
  Blackboard blackboard = contestBoard();
  blackboard.vision.robots = {seenRobot(450.f, 120.f)};
  LineUpAndKick skill;
  for (int frame = 0; frame < STALL_FRAMES; ++frame) skill.tick(blackboard);
  const AbsCoord pos{1500.f, 0.f, 0.9f};
  const auto [x, y] = relative(pos, 92.f, 12.f); // 107 mm from where it was, still at the foot
  Blackboard moved = board(pos, x, y);
  moved.vision.robots = blackboard.vision.robots;
  for (int frame = 0; frame < STALL_FRAMES; ++frame)
    EXPECT_EQ(skill.tick(moved).body.actionType, ActionType::KICK) << frame;
}

TEST(LineUpAndKickSkill, ARobotTheSonarFindsAtTheBallContestsIt) {
  Blackboard blackboard = contestBoard();
  blackboard.motion.sonarLeft = 0.4f; // 400 mm ahead
  EXPECT_EQ(LineUpAndKick().tick(blackboard).body.actionType, ActionType::KICK);
}

TEST(LineUpAndKickSkill, WithCarryAClearBallIsWalkedOnNotKicked) {
  // The ball in front of the left foot, lined up: a kick without carry, a walk into the
  // ball with it, steering its 50 mm off the centre line back under the body.
  EXPECT_EQ(LineUpAndKick().tick(ballAt(130.f, 50.f)).body.actionType, ActionType::KICK);
  LineUpAndKick skill = carrier();
  const auto command = skill.tick(ballAt(130.f, 50.f));
  EXPECT_EQ(command.body.actionType, ActionType::WALK);
  EXPECT_EQ(command.body.forward, CARRY_SPEED);
  expectVelocities(command, CARRY_SPEED, 100.f, 2.f * std::atan2(-50.f, 2870.f));
  EXPECT_TRUE(skill.liningUp());
}

TEST(LineUpAndKickSkill, ACarrierWalksABallOnFromAnAimAKickerWouldWalkRoundTo) {
  const AbsCoord pos{0.f, 0.f, 1.45f}; // the goal 1.5 rad to the right of the ball ahead: beyond a right angle
  const auto [x, y] = relative(pos, 130.f, 0.f);
  LineUpAndKick kicker;
  EXPECT_LT(kicker.tick(board(pos, x, y)).body.forward, CARRY_SPEED);
  EXPECT_FALSE(kicker.liningUp());
  LineUpAndKick carrying = carrier();
  const auto body = carrying.tick(board(pos, x, y)).body;
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_EQ(body.forward, CARRY_SPEED);
  EXPECT_NEAR(body.turn, -LINE_UP_MAX_TURN, 1e-5f);
  EXPECT_TRUE(carrying.liningUp());
}

TEST(LineUpAndKickSkill, ACarrierWalksOnPastARobotAheadAndLeansIntoOneItTouches) {
  // A kick into a robot at the ball often rebounds (in full matches, sometimes out of the field):
  // the carrier walks on. A robot against both foot bumpers contests the ball: the carrier leans
  // into it at CONTEST_LEAN_SPEED rather than stop (two that stop hold the ball between them).
  Blackboard blackboard = ballAt(130.f, 50.f);
  blackboard.vision.robots = {seenRobot(550.f, 150.f)}; // 460 mm beyond the ball
  auto body = carrier().tick(blackboard).body;
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_EQ(body.forward, CARRY_SPEED);
  Blackboard touching = ballAt(130.f, 50.f);
  touching.motion.touchFrontLeft = touching.motion.touchFrontRight = true;
  LineUpAndKick leaning = carrier();
  body = leaning.tick(touching).body;
  EXPECT_TRUE(leaning.contested());
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_EQ(body.forward, CONTEST_LEAN_SPEED);
  EXPECT_NEAR(body.left, 2.f * 50.f - CONTEST_DODGE_SPEED, 1e-3f); // the ball under the body, away from the left bumper's robot
  // Lining up to kick (no carry), the ball short of the foot: the step on is never into the robot.
  Blackboard short_of_foot = ballAt(250.f, 50.f);
  short_of_foot.motion.touchFrontLeft = short_of_foot.motion.touchFrontRight = true;
  EXPECT_LE(LineUpAndKick().tick(short_of_foot).body.forward, 0.f);
}

TEST(LineUpAndKickSkill, ALeaningCarrierKeepsToTheField) {
  // Lined up 40 mm beyond the touchline, turned 0.1 rad further out, a robot against both
  // bumpers: the lean, like any carry, goes along the line, not further out.
  const AbsCoord pos{0.f, FIELD_HALF_WIDTH + 40.f, 0.1f};
  const auto [x, y] = relative(pos, 130.f, 0.f);
  Blackboard touching = board(pos, x, y);
  touching.motion.touchFrontLeft = touching.motion.touchFrontRight = true;
  const auto body = carrier().tick(touching).body;
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_GT(body.forward, 0.f);
  EXPECT_NEAR(body.forward * std::sin(pos.theta) + body.left * std::cos(pos.theta), 0.f, 1e-3f);
}

TEST(LineUpAndKickSkill, AContestedCarrierStepsSidewaysAwayFromTheRobotAtTheBall) {
  // The ball ahead on the centre line, a robot 280 mm beyond it: two carriers walking into one
  // ball wedge it between their feet; the sideways step rolls it off the pair.
  const auto clear = carrier().tick(ballAt(130.f, 0.f));
  EXPECT_EQ(clear.body.actionType, ActionType::WALK);
  expectVelocities(clear, CARRY_SPEED, 0.f, 0.f);
  for (const auto& [robotY, left] : {std::pair{100.f, -CONTEST_DODGE_SPEED}, std::pair{-100.f, CONTEST_DODGE_SPEED}}) {
    Blackboard blackboard = ballAt(130.f, 0.f);
    blackboard.vision.robots = {seenRobot(400.f, robotY)};
    LineUpAndKick skill = carrier();
    const auto body = skill.tick(blackboard).body;
    EXPECT_TRUE(skill.contested());
    EXPECT_EQ(body.actionType, ActionType::WALK);
    EXPECT_EQ(body.forward, CARRY_SPEED);
    EXPECT_NEAR(body.left, left, 1e-3f) << robotY;
  }
}

TEST(LineUpAndKickSkill, ACarrierDoesNotWalkTheBallOffTheField) {
  // Lined up 40 mm beyond the touchline, turned 0.1 rad further out: walking straight on
  // would take it further out; keepClear keeps the walk along the line.
  const AbsCoord pos{0.f, FIELD_HALF_WIDTH + 40.f, 0.1f};
  const auto [x, y] = relative(pos, 130.f, 0.f);
  const auto body = carrier().tick(board(pos, x, y)).body;
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_GT(body.forward, 0.f);
  EXPECT_NEAR(body.forward * std::sin(pos.theta) + body.left * std::cos(pos.theta), 0.f, 1e-3f);
}

TEST(LineUpAndKickSkill, BallTooFarStepsCloser) {
  const auto command = LineUpAndKick().tick(ballAt(250.f, 40.f));
  EXPECT_EQ(command.body.actionType, ActionType::WALK);
  expectVelocities(command, 240.f, -20.f, -0.02909f); // LINE_UP_GAIN x the errors (120 mm, -10 mm)
}

TEST(LineUpAndKickSkill, ACarrierClosesOnABallAheadFasterAndMeetsItAtCarrySpeed) {
  EXPECT_EQ(carrySpeed(KICK_BALL_X), CARRY_SPEED); // at the foot
  EXPECT_EQ(carrySpeed(KICK_BALL_X - 50.f), CARRY_SPEED);
  EXPECT_EQ(carrySpeed(KICK_BALL_X + 30.f), CARRY_SPEED + 30.f * CARRY_CLOSING_GAIN);
  EXPECT_EQ(carrySpeed(400.f), MAX_FORWARD);
  // The skill: the ball 250 mm ahead, lined up with the goal, walked up to at full speed.
  const auto body = carrier().tick(ballAt(250.f, 0.f)).body;
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_EQ(body.forward, MAX_FORWARD);
}

TEST(LineUpAndKickSkill, FootIsKeptWhileLiningUp) {
  LineUpAndKick skill;
  skill.tick(ballAt(250.f, 40.f));
  EXPECT_EQ(skill.foot(), Foot::LEFT);
  const auto command = skill.tick(ballAt(130.f, -20.f)); // now right of centre: left foot still
  EXPECT_EQ(skill.foot(), Foot::LEFT);
  expectVelocities(command, 0.f, -140.f, 0.01394f);
  LineUpAndKick fresh;
  const auto freshBody = fresh.tick(ballAt(130.f, -20.f)).body;
  EXPECT_EQ(fresh.foot(), Foot::RIGHT);
  EXPECT_EQ(freshBody.actionType, ActionType::KICK);
  EXPECT_EQ(freshBody.foot, Foot::RIGHT);
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
