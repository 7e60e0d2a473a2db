// Avoid (issue #17): around robots, out of the own goal box, backing off when blocked; the
// same hand-worked cases as tests/behaviour_py/test_avoid.py.
#include "touchline/behaviour/skills/avoid.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "boards.hpp"
#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;
using touchline::behaviour::test::seenRobot;
using touchline::behaviour::test::teamBoard;

namespace {

constexpr int64_t FRAME_US = 33333;
constexpr int64_t NOW = 10000000;

/// How far the walk's line passes the point (x, y), mm, + when the point is on its left.
float passing(WalkVelocity v, float x, float y) {
  return (v.forward * y - v.left * x) / std::hypot(v.forward, v.left);
}

TeamMessage poseMessage(int number, int x, int y, bool penalised = false, int64_t age = 0) {
  const TeamInfo info{number, ROLE_DEFENDER, false, penalised, false, NO_BALL_DISTANCE, 0, 0, x, y};
  return {number, NOW - age, encodeMessage(info)};
}

/// A board at `pos` with the sonar readings (left, right) at range 1000 mm.
Blackboard sonarBoard(AbsCoord pos, float sonarLeft, float sonarRight, int player = 2, int64_t utime = 0) {
  Blackboard b = teamBoard(pos, 1000.f, 0.f, true, 0, GameState::PLAYING, player, false, false, {}, utime);
  b.motion.sonarLeft = sonarLeft;
  b.motion.sonarRight = sonarRight;
  b.motion.sonarRange_mm = 1000.f;
  return b;
}

void expectVelocity(WalkVelocity v, float forward, float left) {
  EXPECT_NEAR(v.forward, forward, 1e-3f);
  EXPECT_NEAR(v.left, left, 1e-3f);
}

} // namespace

// Where the obstacles come from
TEST(Avoid, ObstaclesFromSonarCameraAndTeammates) {
  const AbsCoord pos{1000.f, 0.f, kPi / 2}; // facing +y
  Blackboard b = sonarBoard(pos, 0.5f, 1.f, 2, NOW);
  b.vision.robots = {seenRobot(700.f, -200.f)};
  b.receiver.messages = {poseMessage(3, 1000, 600), poseMessage(4, 0, 0, true), poseMessage(5, 0, 0, false, 3000000),
                         poseMessage(2, 1000, 900)}; // 2 is this robot: its own message is no obstacle
  const std::vector<Obstacle> found = obstacles(b, remember({}, b));
  ASSERT_EQ(found.size(), 3u);
  EXPECT_NEAR(found[0].x, 500.f, 1e-3f);
  EXPECT_NEAR(found[0].y, SONAR_SIDE_Y, 1e-3f);
  EXPECT_NEAR(found[1].x, 700.f, 1e-3f);
  EXPECT_NEAR(found[1].y, -200.f, 1e-3f);
  EXPECT_NEAR(found[2].x, 600.f, 1e-3f); // the teammate 600 mm ahead
  EXPECT_NEAR(found[2].y, 0.f, 1e-3f);
  const std::vector<Obstacle> right = obstacles(sonarBoard(pos, 1.f, 0.25f));
  ASSERT_EQ(right.size(), 1u);
  EXPECT_NEAR(right[0].x, 250.f, 1e-3f);
  EXPECT_NEAR(right[0].y, -SONAR_SIDE_Y, 1e-3f);
  EXPECT_TRUE(obstacles(sonarBoard(pos, 1.f, 1.f)).empty());
}

TEST(Avoid, ATouchIsARobotAtItsSectorsBearing) {
  Blackboard b = sonarBoard({}, 1.f, 1.f);
  b.motion.touchFrontLeft = b.motion.touchBack = true;
  const std::vector<Obstacle> found = obstacles(b);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0].x, TOUCH_DIST * std::cos(TOUCH_FRONT_BEARING), 1e-3f);
  EXPECT_NEAR(found[0].y, TOUCH_DIST * std::sin(TOUCH_FRONT_BEARING), 1e-3f);
  EXPECT_NEAR(found[1].x, -TOUCH_DIST, 1e-3f);
  EXPECT_NEAR(found[1].y, 0.f, 1e-3f);
  Blackboard right = sonarBoard({}, 1.f, 1.f);
  right.motion.touchFrontRight = true;
  EXPECT_NEAR(obstacles(right)[0].y, -found[0].y, 1e-3f);
  Blackboard sides = sonarBoard({}, 1.f, 1.f);
  sides.motion.touchLeft = sides.motion.touchRight = true;
  const std::vector<Obstacle> beside = obstacles(sides);
  ASSERT_EQ(beside.size(), 2u);
  EXPECT_NEAR(beside[0].x, 0.f, 1e-3f);
  EXPECT_NEAR(beside[0].y, TOUCH_DIST, 1e-3f);
  EXPECT_NEAR(beside[1].y, -TOUCH_DIST, 1e-3f);
}

TEST(Avoid, RobotsSeenAreRememberedForAWhileWhereTheyWere) {
  Blackboard seeing = sonarBoard({0.f, 0.f, 0.f}, 1.f, 1.f, 2, NOW);
  seeing.vision.robots = {seenRobot(700.f, 0.f)};
  std::vector<Sighting> seen = remember({}, seeing);
  const Blackboard later = sonarBoard({100.f, 0.f, kPi / 2}, 1.f, 1.f, 2, NOW + SEEN_MEMORY_US); // moved and turned
  seen = remember(seen, later);
  ASSERT_EQ(seen.size(), 1u);
  const std::vector<Obstacle> found = obstacles(later, seen);
  EXPECT_NEAR(found[0].x, 0.f, 1e-2f); // still at (700, 0): on the right
  EXPECT_NEAR(found[0].y, -600.f, 1e-2f);
  EXPECT_TRUE(remember(seen, sonarBoard({}, 1.f, 1.f, 2, NOW + SEEN_MEMORY_US + 1)).empty());
}

TEST(Avoid, ANewSightingReplacesTheRememberedOnesNearIt) {
  Blackboard first = sonarBoard({}, 1.f, 1.f, 2, NOW);
  first.vision.robots = {seenRobot(700.f, 0.f), seenRobot(700.f, 1000.f)};
  Blackboard second = sonarBoard({}, 1.f, 1.f, 2, NOW + FRAME_US);
  second.vision.robots = {seenRobot(700.f, 300.f)};
  const std::vector<Sighting> seen = remember(remember({}, first), second);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_NEAR(seen[0].y, 1000.f, 1e-2f);
  EXPECT_NEAR(seen[1].x, 700.f, 1e-2f);
  EXPECT_NEAR(seen[1].y, 300.f, 1e-2f);
}

// Around robots
TEST(Avoid, ARobotDeadAheadIsPassedOnTheRightAtTheClearance) {
  const WalkVelocity v = steer(300.f, 0.f, {{500.f, 0.f}}, 2000.f);
  EXPECT_LT(v.left, 0.f);
  EXPECT_GT(v.forward, 0.f);
  EXPECT_NEAR(passing(v, 500.f, 0.f), AVOID_CLEARANCE, 1e-3f);
}

TEST(Avoid, ARobotLeftOfTheLineIsPassedOnItsRightAndOneRightOnItsLeft) {
  EXPECT_NEAR(passing(steer(300.f, 0.f, {{600.f, 100.f}}, 2000.f), 600.f, 100.f), AVOID_CLEARANCE, 1e-3f);
  const WalkVelocity v = steer(300.f, 0.f, {{600.f, -100.f}}, 2000.f);
  EXPECT_GT(v.left, 0.f);
  EXPECT_NEAR(passing(v, 600.f, -100.f), -AVOID_CLEARANCE, 1e-3f);
}

TEST(Avoid, TheNearestRobotInTheWayIsPassed) {
  const WalkVelocity v = steer(0.f, 200.f, {{0.f, 700.f}, {50.f, 450.f}}, 2000.f); // walking left
  EXPECT_NEAR(passing(v, 50.f, 450.f), -AVOID_CLEARANCE, 1e-3f);
}

TEST(Avoid, ATouchingRobotIsSteppedPastSideways) {
  const WalkVelocity v = steer(300.f, 0.f, {{250.f, 10.f}}, 2000.f);
  EXPECT_NEAR(v.forward * 250.f + v.left * 10.f, 0.f, 1e-2f); // nothing towards it
  EXPECT_LT(v.left, 0.f);
}

// Walking forward and left into a robot against the left arm (45 to 135 deg): the walk keeps
// its speed but turns to -45 deg, the nearest direction closing on no bearing of the arm's.
TEST(Avoid, AWalkIntoARobotItFeelsButNeverSawTurnsAwayFromIt) {
  const ActionCommand::Body walk = touchline::behaviour::actioncommand::walk(200.f, 200.f, 0.f);
  const ActionCommand::Body free = Avoid().tick(sonarBoard({}, 1.f, 1.f, 2, NOW), walk, 2000.f);
  EXPECT_NEAR(free.forward, 200.f, 1e-3f);
  EXPECT_NEAR(free.left, 200.f, 1e-3f);
  Blackboard touched = sonarBoard({}, 1.f, 1.f, 2, NOW);
  touched.motion.touchLeft = true;
  const ActionCommand::Body body = Avoid().tick(touched, walk, 2000.f);
  EXPECT_NEAR(body.forward, 200.f, 1e-2f);
  EXPECT_NEAR(body.left, -200.f, 1e-2f);
}

TEST(Avoid, AWalkClosingOnNoTouchedSectorIsLeftAlone) {
  MotionBlackboard left;
  left.touchLeft = true;
  expectVelocity(keepOffTouches(left, 300.f, 0.f), 200.f, -200.f); // turned to -45 deg, clampWalk's
  expectVelocity(keepOffTouches(left, 0.f, -200.f), 0.f, -200.f);
  MotionBlackboard back;
  back.touchBack = true;
  expectVelocity(keepOffTouches(back, 300.f, 0.f), 300.f, 0.f);
  expectVelocity(keepOffTouches(MotionBlackboard{}, 0.f, 200.f), 0.f, 200.f);
}

TEST(Avoid, PressedOnBothFootBumpersItStepsBackAndBoxedInItStops) {
  MotionBlackboard bumpers;
  bumpers.touchFrontLeft = bumpers.touchFrontRight = true;
  const WalkVelocity v = keepOffTouches(bumpers, 200.f, 0.f);
  EXPECT_NEAR(std::atan2(v.left, v.forward), 3 * kPi / 4, 1e-4f); // back left: the first of two equal turns
  EXPECT_NEAR(std::hypot(v.forward, v.left), 200.f, 1e-2f);
  MotionBlackboard boxed;
  boxed.touchFrontLeft = boxed.touchLeft = boxed.touchRight = boxed.touchBack = true;
  expectVelocity(keepOffTouches(boxed, 200.f, 0.f), 0.f, 0.f);
}

TEST(Avoid, RobotsOutOfTheWayAreLeftAlone) {
  expectVelocity(steer(300.f, 0.f, {{500.f, 450.f}}, 2000.f), 300.f, 0.f);  // off the line
  expectVelocity(steer(300.f, 0.f, {{900.f, 0.f}}, 2000.f), 300.f, 0.f);    // beyond the lookahead
  expectVelocity(steer(300.f, 0.f, {{-300.f, 0.f}}, 2000.f), 300.f, 0.f);   // behind
  expectVelocity(steer(300.f, 0.f, {{500.f, 0.f}}, 400.f), 300.f, 0.f);     // beyond the target
  expectVelocity(steer(0.f, 0.f, {{300.f, 0.f}}, 2000.f), 0.f, 0.f);        // turning on the spot
}

TEST(Avoid, GoToPoseWalksAroundARobotItsSonarFinds) {
  const ActionCommand::Body clear = GoToPose(2000.f, 0.f, 0.f).tick(board({0.f, 0.f, 0.f})).body;
  EXPECT_NEAR(clear.forward, 300.f, 1e-3f);
  EXPECT_NEAR(clear.left, 0.f, 1e-3f);
  const ActionCommand::Body blocked = GoToPose(2000.f, 0.f, 0.f).tick(sonarBoard({0.f, 0.f, 0.f}, 0.5f, 0.5f)).body;
  EXPECT_LT(blocked.left, 0.f);
  EXPECT_NEAR(blocked.turn, clear.turn, 1e-5f);
}

TEST(Avoid, ARobotSeenOnceIsWalkedAroundAfterTheCameraLookedAway) {
  GoToPose goToPose(2000.f, 0.f, 0.f);
  Blackboard seeing = sonarBoard({}, 1.f, 1.f, 2, NOW);
  seeing.vision.robots = {seenRobot(600.f, 0.f)};
  goToPose.tick(seeing);
  EXPECT_LT(goToPose.tick(sonarBoard({}, 1.f, 1.f, 2, NOW + FRAME_US)).body.left, 0.f);
}

// Making way
TEST(Avoid, MakingWayNeverStepsBackIntoARobotTouchingTheBack) {
  GoToPose goToPose(0.f, 0.f, 0.f);
  Blackboard b = sonarBoard({}, 0.3f, 1.f, 2, NOW);
  b.motion.touchBack = true;
  const ActionCommand::Body body = goToPose.tick(b).body;
  EXPECT_EQ(body.actionType, ActionCommand::ActionType::WALK);
  EXPECT_GE(body.forward, 0.f);
  EXPECT_LT(body.left, 0.f); // aside, away from the robot ahead on the left
}

TEST(Avoid, ARobotAtItsTargetStepsBackFromARobotAheadOfIt) {
  GoToPose goToPose(0.f, 0.f, 0.f);
  EXPECT_EQ(goToPose.tick(sonarBoard({}, 1.f, 1.f, 2, NOW)).body.actionType, ActionCommand::ActionType::STAND);
  const ActionCommand::Body body = goToPose.tick(sonarBoard({}, 0.3f, 1.f, 2, NOW + FRAME_US)).body;
  EXPECT_EQ(body.actionType, ActionCommand::ActionType::WALK);
  EXPECT_NEAR(body.forward * 300.f + body.left * SONAR_SIDE_Y, -150.f * std::hypot(300.f, SONAR_SIDE_Y), 1e-2f);
  Blackboard behind = sonarBoard({}, 1.f, 1.f, 2, NOW + 2 * FRAME_US);
  behind.vision.robots = {seenRobot(-300.f, 0.f)};
  EXPECT_EQ(goToPose.tick(behind).body.actionType, ActionCommand::ActionType::STAND);
}

// The own goal box
TEST(Avoid, AWalkIntoTheOwnGoalBoxSlidesAlongItsFront) {
  const AbsCoord pos{-2200.f, 300.f, kPi}; // in front of the box, facing the own goal
  expectVelocity(keepOutOfOwnBox(pos, 300.f, 0.f), 0.f, 0.f);
  expectVelocity(keepOutOfOwnBox(pos, 200.f, -200.f), 0.f, -200.f); // back and to the field's +y: slides along +y
  expectVelocity(keepOutOfOwnBox(pos, -200.f, 50.f), -200.f, 50.f); // away from it
}

TEST(Avoid, BesideTheBoxAWalkAcrossItGoesRoundByTheFront) {
  expectVelocity(keepOutOfOwnBox({-2700.f, 1400.f, 0.f}, 0.f, -200.f), 200.f, 0.f); // sideways across the box
}

TEST(Avoid, TheGoalieAndARobotInTheBoxWalkAsAsked) {
  expectVelocity(keepOutOfOwnBox({-2700.f, 0.f, kPi}, 300.f, 0.f), 300.f, 0.f);
  const AbsCoord outside{-2200.f, 0.f, kPi};
  const ActionCommand::Body walk = touchline::behaviour::actioncommand::walk(300.f, 0.f, 0.f);
  EXPECT_NEAR(Avoid().tick(sonarBoard(outside, 1.f, 1.f, 1), walk, 2000.f).forward, 300.f, 1e-3f);
  EXPECT_NEAR(Avoid().tick(sonarBoard(outside, 1.f, 1.f, 3), walk, 2000.f).forward, 0.f, 1e-3f);
}

TEST(Avoid, AWalkTheBoxTurnsBackIntoATouchingRobotStops) {
  // Beside the own box, sidestepping towards it: the box sends the walk round its front,
  // forward; with an opponent against the left foot bumper, forward is into it: wait instead.
  const AbsCoord beside{-2700.f, 1400.f, 0.f};
  const ActionCommand::Body sidestep = touchline::behaviour::actioncommand::walk(0.f, -200.f, 0.f);
  const ActionCommand::Body free = Avoid().tick(sonarBoard(beside, 1.f, 1.f, 3, NOW), sidestep, 2000.f);
  EXPECT_NEAR(free.forward, 200.f, 1e-3f);
  EXPECT_NEAR(free.left, 0.f, 1e-3f);
  Blackboard touched = sonarBoard(beside, 1.f, 1.f, 3, NOW);
  touched.motion.touchFrontLeft = true;
  const ActionCommand::Body waiting = Avoid().tick(touched, sidestep, 2000.f);
  EXPECT_EQ(waiting.forward, 0.f);
  EXPECT_EQ(waiting.left, 0.f);
}

TEST(Avoid, KeepInBoundsKeepsTheBoxAndTheLinesButNotTheTouches) {
  // Beside the own box, sidestepping towards it, an opponent against the left foot bumper:
  // keepInBounds sends the walk round the box's front, into the robot (keepClear waits), and
  // for the goalie leaves it as asked; at the touchline it drops the part out, as keepClear does.
  Blackboard touched = sonarBoard({-2700.f, 1400.f, 0.f}, 1.f, 1.f, 3, NOW);
  touched.motion.touchFrontLeft = true;
  expectVelocity(keepInBounds(touched, 0.f, -200.f), 200.f, 0.f);
  expectVelocity(keepClear(touched, 0.f, -200.f), 0.f, 0.f);
  touched.gameController.playerNumber = 1;
  expectVelocity(keepInBounds(touched, 0.f, -200.f), 0.f, -200.f);
  Blackboard atLine = sonarBoard({0.f, 1950.f, kPi / 2}, 1.f, 1.f, 3, NOW); // facing out
  expectVelocity(keepInBounds(atLine, 200.f, 200.f), 0.f, 200.f);
}

// The field
TEST(Avoid, AWalkOverATouchlineLosesItsPartOutAndKeepsItsPartAlong) {
  const AbsCoord atLine{0.f, 1950.f, kPi / 2}; // on the +y touchline's inside, facing out
  expectVelocity(keepOnField(atLine, 300.f, 0.f), 0.f, 0.f);      // straight out: stops
  expectVelocity(keepOnField(atLine, 200.f, 200.f), 0.f, 200.f);  // out and along -x: only along
  expectVelocity(keepOnField(atLine, -300.f, 0.f), -300.f, 0.f);  // back in
  expectVelocity(keepOnField({0.f, 1700.f, kPi / 2}, 300.f, 0.f), 300.f, 0.f); // out, but not past the slack
}

TEST(Avoid, BeyondAGoalLineARobotMayOnlyWalkBackIn) {
  const AbsCoord beyond{-3100.f, 500.f, 0.f}; // behind the own goal line, facing the field
  expectVelocity(keepOnField(beyond, -200.f, 0.f), 0.f, 0.f);
  expectVelocity(keepOnField(beyond, 200.f, 0.f), 200.f, 0.f);
  expectVelocity(keepOnField(beyond, -200.f, 100.f), 0.f, 100.f);
}

TEST(Avoid, EveryPlayerTheGoalieTooStaysOnTheField) {
  const AbsCoord atLine{0.f, -1980.f, 0.f}; // on the -y touchline, facing along it
  const ActionCommand::Body out = touchline::behaviour::actioncommand::walk(0.f, -200.f, 0.f);
  for (int player : {1, 2})
    EXPECT_NEAR(Avoid().tick(sonarBoard(atLine, 1.f, 1.f, player), out, 2000.f).left, 0.f, 1e-3f) << player;
}

// Backing off
namespace {

std::vector<ActionCommand::Body> run(Avoid& avoid, int frames, float sonarLeft = 0.3f, float sonarRight = 1.f,
                                     int start = 0, bool touchBack = false) {
  const ActionCommand::Body walk = touchline::behaviour::actioncommand::walk(300.f, 0.f, 0.f);
  std::vector<ActionCommand::Body> bodies;
  for (int i = 0; i < frames; ++i) {
    Blackboard b = sonarBoard({}, sonarLeft, sonarRight, 2, NOW + (start + i) * FRAME_US);
    b.motion.touchBack = touchBack;
    bodies.push_back(avoid.tick(b, walk, 2000.f));
  }
  return bodies;
}

} // namespace

TEST(Avoid, BlockedWithoutProgressBacksOffThenWalksAgain) {
  Avoid avoid;
  for (const auto& body : run(avoid, BLOCKED_FRAMES - 1)) EXPECT_GT(body.forward, 0.f);
  for (const auto& body : run(avoid, BACK_OFF_FRAMES, 0.3f, 1.f, BLOCKED_FRAMES - 1)) {
    EXPECT_LT(body.forward, 0.f);
    EXPECT_LT(body.left, 0.f); // away from a left obstacle
    EXPECT_EQ(body.turn, 0.f);
  }
  EXPECT_GT(run(avoid, 1, 0.3f, 1.f, BLOCKED_FRAMES - 1 + BACK_OFF_FRAMES)[0].forward, 0.f);
}

TEST(Avoid, AnObstacleOnTheRightIsBackedOffToTheLeft) {
  Avoid avoid;
  const auto bodies = run(avoid, BLOCKED_FRAMES, 1.f, 0.3f);
  EXPECT_LT(bodies.back().forward, 0.f);
  EXPECT_GT(bodies.back().left, 0.f);
}

TEST(Avoid, BackingOffNeverStepsBackIntoARobotTouchingTheBack) {
  Avoid avoid;
  const auto bodies = run(avoid, BLOCKED_FRAMES, 0.3f, 1.f, 0, true);
  EXPECT_GE(bodies.back().forward, 0.f);
  EXPECT_LT(bodies.back().left, 0.f); // aside, still away from the left
}

TEST(Avoid, ProgressOrAClearWayIsNoBlock) {
  Avoid avoid;
  const ActionCommand::Body walk = touchline::behaviour::actioncommand::walk(300.f, 0.f, 0.f);
  for (int i = 0; i < 3 * BLOCKED_FRAMES; ++i) // 5 mm a frame nearer
    EXPECT_GT(avoid.tick(sonarBoard({}, 0.3f, 1.f, 2, NOW + i * FRAME_US), walk, 2000.f - 5.f * i).forward, 0.f);
  Avoid clear;
  for (const auto& body : run(clear, 3 * BLOCKED_FRAMES, 1.f, 1.f)) EXPECT_GT(body.forward, 0.f);
}

TEST(Avoid, AGapInTheTicksStartsTheCountAgain) {
  Avoid avoid;
  run(avoid, BLOCKED_FRAMES - 1);
  for (const auto& body : run(avoid, BLOCKED_FRAMES - 1, 0.3f, 1.f, BLOCKED_FRAMES + 10)) EXPECT_GT(body.forward, 0.f);
}
