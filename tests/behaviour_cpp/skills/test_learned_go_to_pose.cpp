// LearnedGoToPose and the skills that walk to the ball with it (GoToBall, LineUpAndKick,
// Striker, Team with a policy); the same cases as tests/behaviour_py/test_learned_go_to_pose.py,
// with the worked states of test_tile_policy and the test policy of policy_files.hpp.
#include "touchline/behaviour/skills/learned_go_to_pose.hpp"

#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "boards.hpp"
#include "rejection.hpp"
#include "policy_files.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/behaviour/skills/go_to_ball.hpp"
#include "touchline/behaviour/skills/line_up_and_kick.hpp"
#include "touchline/behaviour/skills/striker.hpp"
#include "touchline/behaviour/skills/team.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::make_behaviour;
using touchline::behaviour::test::board;
using touchline::behaviour::test::rejection;
using touchline::behaviour::test::TestDataDir;
using touchline::behaviour::test::writePolicy;
using ActionCommand::ActionType;

namespace {

constexpr double kPiD = 3.14159265358979323846;
const std::string POLICY = "policies/go_to_pose.policy";
using Body = std::tuple<ActionType, float, float, float>;
const Body FORWARD{ActionType::WALK, 300.f, 0.f, 0.f};
const Body LEFT{ActionType::WALK, 0.f, 0.f, 1.f};
const Body RIGHT{ActionType::WALK, 0.f, 0.f, -1.f};

Body body(const ActionCommand::All& command) {
  return {command.body.actionType, command.body.forward, command.body.left, command.body.turn};
}

} // namespace

TEST(LearnedGoToPose, RelativeTargetTurnsTheFieldIntoTheRobotFrame) {
  RelativeTarget t = relativeTarget({0.f, 0.f, static_cast<float>(kPiD / 2)}, -500.0, 1000.0, kPiD / 2 + 0.5);
  EXPECT_NEAR(t.x, 1000.0, 1e-4);
  EXPECT_NEAR(t.y, 500.0, 1e-4);
  EXPECT_NEAR(t.theta, 0.5, 1e-4);
  t = relativeTarget({1000.f, 1000.f, static_cast<float>(kPiD)}, 0.0, 1000.0, 0.0);
  EXPECT_NEAR(t.x, 1000.0, 1e-4);
  EXPECT_NEAR(t.y, 0.0, 1e-4);
  EXPECT_NEAR(t.theta, -kPiD, 1e-6); // not wrapped: the policy wraps it
}

TEST(LearnedGoToPose, WalksWithTheGreedyAction) {
  const TestDataDir data;
  EXPECT_EQ(body(LearnedGoToPose(1000.0, 500.0, 0.5).tick(board({0, 0, 0}))), FORWARD);
  EXPECT_EQ(body(LearnedGoToPose(-200.0, 800.0, 0.0).tick(board({0, 0, 0}))), LEFT);
  EXPECT_EQ(body(LearnedGoToPose(-300.0, -600.0, 0.0).tick(board({0, 0, 0}))), RIGHT);
}

TEST(LearnedGoToPose, TargetInTheTeamFrame) {
  const TestDataDir data;
  // Facing +y, the target 1000 mm ahead and 500 mm left is the worked state (1000, 500, 0.5).
  const AbsCoord facingLeft{0.f, 0.f, static_cast<float>(kPiD / 2)};
  LearnedGoToPose skill(-500.0, 1000.0, kPiD / 2 + 0.5);
  EXPECT_EQ(body(skill.tick(board(facingLeft))), FORWARD);
  skill.setTarget(-800.0, -200.0, kPiD / 2); // (-200, 800) seen from the robot: turn left
  EXPECT_EQ(body(skill.tick(board(facingLeft))), LEFT);
}

TEST(LearnedGoToPose, StandsInsideTheSuccessTolerances) {
  const TestDataDir data;
  EXPECT_EQ(LearnedGoToPose(1030.0, -20.0, 0.1).tick(board({1000.f, 0.f, 0.f})).body.actionType, ActionType::STAND);
  EXPECT_EQ(LearnedGoToPose(1030.0, -20.0, 0.2).tick(board({1000.f, 0.f, 0.f})).body.actionType, ActionType::WALK);
}

TEST(LearnedGoToPose, ThePolicyFileIsReadOnce) {
  const TestDataDir data;
  EXPECT_EQ(&LearnedGoToPose().policy(), &LearnedGoToPose(100.0, 0.0, 0.0).policy());
}

TEST(LearnedGoToPose, PolicyPathIsRelativeToTheDataDirectory) {
  const TestDataDir data;
  writePolicy(data.path() / "other" / "short.policy", "touchline-policy 1\n");
  EXPECT_EQ(rejection("LearnedGoToPose", {{"policy", "other/short.policy"}}),
            (data.path() / "other" / "short.policy").string() + ": missing 'features'");
}

TEST(LearnedGoToPose, AMissingPolicyIsNamedAtConstruction) {
  const TestDataDir data;
  EXPECT_EQ(rejection("LearnedGoToPose", {{"policy", "policies/none.policy"}}),
            (data.path() / "policies" / "none.policy").string() + ": cannot read the policy (No such file or directory)");
}

TEST(LearnedGoToPose, GoToBallWalksBehindTheBallWithThePolicy) {
  const TestDataDir data;
  GoToBall skill(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, BEHIND_BALL_DIST, POLICY);
  // Behind the ball (1000, 0) facing the goal is (800, 0, 0).
  EXPECT_EQ(body(skill.tick(board({0.f, 0.f, 0.f}, 1000.f, 0.f))), FORWARD);
  EXPECT_EQ(body(skill.tick(board({1100.f, 600.f, 0.f}, 1000.f, 0.f))), RIGHT); // (-300, -600)
  EXPECT_EQ(skill.tick(board({800.f, 0.f, 0.f}, 1000.f, 0.f)).body.actionType, ActionType::STAND);
  EXPECT_NE(body(GoToBall().tick(board({1100.f, 600.f, 0.f}, 1000.f, 0.f))), RIGHT); // hand walker
}

TEST(LearnedGoToPose, LineUpAndKickStrikerAndTeamApproachWithThePolicy) {
  const TestDataDir data;
  const Blackboard blackboard = board({1100.f, 600.f, 0.f}, 1000.f, 0.f);
  EXPECT_EQ(body(LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, false, std::nullopt, POLICY).tick(blackboard)), RIGHT);
  EXPECT_EQ(body(Striker(POLICY).tick(blackboard)), RIGHT);
  Blackboard playing = blackboard;
  playing.gameController.state = GameState::PLAYING;
  playing.gameController.playerNumber = 2;
  EXPECT_EQ(body(Team(ROLE_STRIKER, POLICY).tick(playing)), RIGHT);
}

TEST(LearnedGoToPose, BehaviourParamsPickTheLearnedWalker) {
  const TestDataDir data;
  Blackboard blackboard = board({1100.f, 600.f, 0.f}, 1000.f, 0.f);
  blackboard.gameController.state = GameState::PLAYING;
  blackboard.gameController.playerNumber = 2;
  for (const std::string skill : {"GoToBall", "LineUpAndKick", "Striker", "Team"}) {
    EXPECT_EQ(body(make_behaviour(skill, {{"walker", "learned"}})->tick(blackboard)), RIGHT) << skill;
    EXPECT_EQ(body(make_behaviour(skill, {{"walker", "learned"}, {"policy", POLICY}})->tick(blackboard)), RIGHT) << skill;
  }
  EXPECT_EQ(body(make_behaviour("LearnedGoToPose", {{"x", "-200"}, {"y", "800"}})->tick(board())), LEFT);
}

TEST(LearnedGoToPose, BadWalkerParametersAreRejected) {
  const TestDataDir data;
  EXPECT_EQ(rejection("GoToBall", {{"walker", "neural"}}),
            "GoToBall: parameter walker must be hand or learned (got 'neural')");
  EXPECT_EQ(rejection("Team", {{"policy", POLICY}}), "Team: parameter policy needs walker=learned");
  EXPECT_EQ(rejection("LearnedGoToPose", {{"walker", "learned"}}), "LearnedGoToPose: unknown parameter 'walker'");
  EXPECT_EQ(rejection("LearnedGoToPose", {{"x", "1m"}}), "LearnedGoToPose: parameter x must be a number (got '1m')");
}
