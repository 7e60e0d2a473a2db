// The skills by name from the registry, composed with the head skill and LEDs; the same
// cases as tests/behaviour_py/test_behaviour.py.
#include "touchline/behaviour/skills/skill_behaviour.hpp"

#include <gtest/gtest.h>

#include "boards.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/head_scan.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::BehaviourError;
using touchline::behaviour::make_behaviour;
using touchline::behaviour::test::board;
using ActionCommand::ActionType;

TEST(SkillBehaviour, GoToBallWithTheHeadOnTheBall) {
  const auto command = make_behaviour("GoToBall", {})->tick(board({0, 0, 0}, 1000.f, 0.f));
  EXPECT_EQ(command.body.actionType, ActionType::WALK);
  EXPECT_NEAR(command.body.forward, 300.f, 1e-3f);
  EXPECT_NEAR(command.head.yaw, 0.f, 1e-5f);
  EXPECT_NEAR(command.head.pitch, 0.313333f, 1e-5f);
  EXPECT_EQ(command.leds.chest, BALL_SEEN_CHEST);
}

TEST(SkillBehaviour, LostBallStandsScansAndShowsRed) {
  const auto command =
      make_behaviour("GoToBall", {})->tick(board({0, 0, 0}, 1000.f, 500.f, false, BALL_LOST_FRAMES + 1));
  EXPECT_EQ(command.body.actionType, ActionType::STAND);
  EXPECT_NEAR(command.head.yaw, SCAN_YAW_STEP, 1e-6f);
  EXPECT_NEAR(command.head.pitch, SCAN_PITCH, 1e-6f);
  EXPECT_EQ(command.leds.chest, BALL_LOST_CHEST);
}

TEST(SkillBehaviour, KeepsItsSkillStateAcrossTicks) {
  auto behaviour = make_behaviour("HeadScan", {});
  const Blackboard blackboard = board({0, 0, 0}, 1000.f, 500.f);
  for (int i = 1; i <= 3; ++i) EXPECT_NEAR(behaviour->tick(blackboard).head.yaw, static_cast<float>(i) * SCAN_YAW_STEP, 1e-5f);
  EXPECT_EQ(behaviour->tick(blackboard).body.actionType, ActionType::STAND);
}

TEST(SkillBehaviour, GoToPoseTakesItsParameters) {
  auto command = make_behaviour("GoToPose", {{"x", "-2000"}, {"y", "-100"}, {"theta", "0"}})->tick(board({0, 0, 0}));
  EXPECT_NEAR(command.body.forward, -200.f, 1e-3f); // behind, ending facing +x
  EXPECT_NEAR(command.body.turn, 0.f, 1e-5f);
  command = make_behaviour("GoToPose", {{"x", "0"}, {"y", "0"}, {"face_ball", "1"}})->tick(board({0, 0, 0}, 0.f, 1000.f));
  EXPECT_NEAR(command.body.turn, 1.5f, 1e-5f);
}

TEST(SkillBehaviour, LineUpAndKickAndTrackBallByName) {
  EXPECT_EQ(make_behaviour("LineUpAndKick", {{"dribble", "1"}})->tick(board({0, 0, 0}, 130.f, -50.f)).body.actionType,
            ActionType::DRIBBLE);
  const auto command = make_behaviour("TrackBall", {})->tick(board({0, 0, 0}, 1000.f, 0.f, false, 100));
  EXPECT_EQ(command.body.actionType, ActionType::STAND);
  EXPECT_NEAR(command.head.pitch, 0.313333f, 1e-5f); // tracks even when lost
}

TEST(SkillBehaviour, BadParametersAreRejected) {
  EXPECT_THROW(make_behaviour("GoToPose", {{"x", "12abc"}}), BehaviourError);
  EXPECT_THROW(make_behaviour("GoToPose", {{"z", "1"}}), BehaviourError);
  EXPECT_THROW(make_behaviour("GoToBall", {{"goal_x", ""}}), BehaviourError);
  EXPECT_THROW(make_behaviour("GoToBall", {{"goal_x", "nan"}}), BehaviourError);
  EXPECT_THROW(make_behaviour("LineUpAndKick", {{"power", "1 "}}), BehaviourError);
  EXPECT_THROW(make_behaviour("TrackBall", {{"x", "1"}}), BehaviourError);
}
