// The adapters that write the Blackboard from a sensed frame: here the game controller's
// (every state and set play mapped by name, not by number) and the fall adapter's.
#include "touchline/robot/adapters.hpp"

#include <gtest/gtest.h>

namespace touchline::robot {
namespace {

api::GameControllerBlackboard written(const GameInfo& game, RobotId id = {1, 3}, bool penalised = false) {
  SenseFrame frame;
  frame.utime = 123456;
  frame.game = game;
  RobotSense sense;
  sense.id = id;
  sense.penalised = penalised;
  api::Blackboard blackboard;
  write_game_controller(frame, sense, blackboard);
  EXPECT_EQ(blackboard.utime, 123456);
  return blackboard.gameController;
}

TEST(GameControllerAdapter, EveryStateReachesTheBlackboard) {
  const std::pair<GameState, api::GameState> states[] = {
      {GameState::kInitial, api::GameState::INITIAL}, {GameState::kReady, api::GameState::READY},
      {GameState::kSet, api::GameState::SET},         {GameState::kPlaying, api::GameState::PLAYING},
      {GameState::kFinished, api::GameState::FINISHED}, {GameState::kStandby, api::GameState::STANDBY}};
  for (const auto& [sensed, expected] : states) {
    GameInfo game;
    game.state = sensed;
    EXPECT_EQ(written(game).state, expected) << to_string(sensed);
  }
}

TEST(GameControllerAdapter, EverySetPlayAndItsTeamReachTheBlackboard) {
  const std::pair<SetPlay, api::SetPlay> set_plays[] = {
      {SetPlay::kGoalKick, api::SetPlay::GOAL_KICK},       {SetPlay::kPushingFreeKick, api::SetPlay::PUSHING_FREE_KICK},
      {SetPlay::kCornerKick, api::SetPlay::CORNER_KICK},   {SetPlay::kKickIn, api::SetPlay::KICK_IN},
      {SetPlay::kPenaltyKick, api::SetPlay::PENALTY_KICK}};
  for (const auto& [sensed, expected] : set_plays) {
    GameInfo game;
    game.set_play = sensed;
    game.set_play_team = 0;
    const api::GameControllerBlackboard gc = written(game);
    EXPECT_EQ(gc.setPlay, expected) << to_string(sensed);
    EXPECT_EQ(gc.setPlayTeam, 0);
  }
  const api::GameControllerBlackboard none = written(GameInfo{});
  EXPECT_EQ(none.setPlay, api::SetPlay::NONE);
  EXPECT_EQ(none.setPlayTeam, -1);
  EXPECT_EQ(none.dropInTeam, -1);
  EXPECT_EQ(none.dropInTime, -1);
}

TEST(GameControllerAdapter, TheLastDropInReachesTheBlackboard) {
  GameInfo game;
  game.drop_in_team = 1;
  game.drop_in_s = 7;
  const api::GameControllerBlackboard gc = written(game);
  EXPECT_EQ(gc.dropInTeam, 1);
  EXPECT_EQ(gc.dropInTime, 7);
}

TEST(GameControllerAdapter, WhoTheRobotIsAndTheScoreReachTheBlackboard) {
  GameInfo game;
  game.score = {{4, 1}};
  game.secs_remaining = 321;
  const api::GameControllerBlackboard gc = written(game, {1, 3}, true);
  EXPECT_EQ(gc.team, 1);
  EXPECT_EQ(gc.playerNumber, 3);
  EXPECT_TRUE(gc.penalised);
  EXPECT_EQ(gc.score, (std::array<int, 2>{{4, 1}}));
  EXPECT_EQ(gc.secsRemaining, 321);
}

// What the robot feels reaches MotionBlackboard: lying down, the sonars, the touch sensors.
TEST(FallAdapter, TheFallTheSonarsAndTheTouchesReachTheBlackboard) {
  RobotSense sense;
  sense.fallen = true;
  sense.sonar_left = 0.25f;
  sense.touch.front_left = sense.touch.back = true;
  api::Blackboard blackboard;
  write_fall(sense, blackboard);
  const api::MotionBlackboard& m = blackboard.motion;
  EXPECT_TRUE(m.fallen);
  EXPECT_EQ(m.sonarLeft, 0.25f);
  EXPECT_EQ(m.sonarRight, 1.f);
  EXPECT_TRUE(m.touchFrontLeft && m.touchBack);
  EXPECT_FALSE(m.touchFrontRight || m.touchLeft || m.touchRight);
  sense.touch = Touch{};
  write_fall(sense, blackboard);
  EXPECT_FALSE(blackboard.motion.touchFrontLeft || blackboard.motion.touchBack) << "a touch lasts its frame";
}

} // namespace
} // namespace touchline::robot
