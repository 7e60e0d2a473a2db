#include "touchline/lcm/snapshot.hpp"

#include "touchline/lcm/codec.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

using namespace touchline;
namespace AC = api::ActionCommand;

namespace {

api::Blackboard sample() {
  api::Blackboard bb;
  bb.utime = 1233330;
  bb.behaviour.skill = "GoToBall";
  bb.motion.odometry = {12, -34, 0.5f};
  bb.motion.active = AC::walk(200, -50, 0.25f);
  bb.motion.headYaw = 0.3f;
  bb.motion.headPitch = 0.1f;
  bb.motion.standing = false;
  bb.motion.ticks = 3700;
  bb.motion.kickPhase = 2;
  bb.motion.sonarLeft = 0.4f;
  bb.motion.sonarRight = 0.9f;
  bb.motion.sonarRange_mm = 1200;
  bb.motion.touchLeft = true;
  bb.localisation.robotPos = {-1000, 500, 1.5f};
  bb.localisation.ballPos = {200, 100, 0};
  bb.localisation.ballPosRR = {1250, -0.75f};
  bb.localisation.ballLostCount = 4;
  bb.localisation.teamBallPos = {210, 90, 0};
  bb.vision.ballSeen = true;
  bb.vision.ball = {1240, -0.7f};
  bb.vision.frame = 37;
  bb.vision.robots = {{{600, 0.2f}, 4, true}, {{900, -0.5f}, 2, false}};
  bb.gameController.state = api::GameState::PLAYING;
  bb.gameController.team = 1;
  bb.gameController.playerNumber = 3;
  bb.gameController.penalised = true;
  bb.gameController.score = {{2, 1}};
  bb.gameController.secsRemaining = 412;
  bb.gameController.dropInTeam = 0;
  bb.gameController.dropInTime = 3;
  bb.behaviour.request.head.yaw = -0.4f;
  bb.behaviour.request.head.isRelative = true;
  bb.behaviour.request.body.actionType = AC::ActionType::KICK;
  bb.behaviour.request.body.foot = AC::Foot::RIGHT;
  bb.behaviour.request.body.power = 0.8f;
  bb.behaviour.request.leds.chest = 0x0000ff;
  bb.receiver.messages = {{2, 1200000, {1, 2, 3}}, {4, 1100000, {}}};
  return bb;
}

} // namespace

TEST(Snapshot, BlackboardSurvivesEncodeAndDecode) {
  const api::Blackboard in = sample();
  const blackboard_snapshot_t msg = transport::to_snapshot(in, {1, 3}, 37);
  std::vector<uint8_t> bytes(static_cast<size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  blackboard_snapshot_t decoded;
  ASSERT_GT(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  EXPECT_EQ(decoded.frame, 37);
  EXPECT_EQ(decoded.team, 1);
  const api::Blackboard out = transport::from_snapshot(decoded);

  EXPECT_EQ(out.utime, in.utime);
  EXPECT_EQ(out.behaviour.skill, "GoToBall");
  EXPECT_EQ(out.motion.odometry.theta, in.motion.odometry.theta);
  EXPECT_EQ(out.motion.active.actionType, AC::ActionType::WALK);
  EXPECT_EQ(out.motion.active.left, -50);
  EXPECT_EQ(out.motion.ticks, 3700);
  EXPECT_EQ(out.motion.kickPhase, 2);
  EXPECT_FALSE(out.motion.standing);
  EXPECT_EQ(out.localisation.robotPos.y, 500);
  EXPECT_EQ(out.localisation.ballPosRR.heading, -0.75f);
  EXPECT_EQ(out.localisation.ballLostCount, 4);
  EXPECT_EQ(out.localisation.teamBallPos.x, 210);
  EXPECT_TRUE(out.vision.ballSeen);
  EXPECT_EQ(out.vision.ball.distance, 1240);
  EXPECT_EQ(out.vision.frame, 37);
  EXPECT_EQ(out.motion.sonarLeft, 0.4f);
  EXPECT_EQ(out.motion.sonarRight, 0.9f);
  EXPECT_EQ(out.motion.sonarRange_mm, 1200);
  EXPECT_TRUE(out.motion.touchLeft);
  EXPECT_FALSE(out.motion.touchFrontLeft || out.motion.touchFrontRight || out.motion.touchRight || out.motion.touchBack);
  ASSERT_EQ(out.vision.robots.size(), 2u);
  EXPECT_EQ(out.vision.robots[0].rr.distance, 600);
  EXPECT_EQ(out.vision.robots[0].id, 4);
  EXPECT_TRUE(out.vision.robots[0].teammate);
  EXPECT_EQ(out.vision.robots[1].rr.heading, -0.5f);
  EXPECT_EQ(out.vision.robots[1].id, 2);
  EXPECT_FALSE(out.vision.robots[1].teammate);
  EXPECT_EQ(out.gameController.state, api::GameState::PLAYING);
  EXPECT_EQ(out.gameController.playerNumber, 3);
  EXPECT_TRUE(out.gameController.penalised);
  EXPECT_EQ(out.gameController.score[0], 2);
  EXPECT_EQ(out.gameController.secsRemaining, 412);
  EXPECT_EQ(out.gameController.dropInTeam, 0);
  EXPECT_EQ(out.gameController.dropInTime, 3);
  EXPECT_EQ(out.behaviour.request.head.yaw, -0.4f);
  EXPECT_TRUE(out.behaviour.request.head.isRelative);
  EXPECT_EQ(out.behaviour.request.body.actionType, AC::ActionType::KICK);
  EXPECT_EQ(out.behaviour.request.body.foot, AC::Foot::RIGHT);
  EXPECT_EQ(out.behaviour.request.body.power, 0.8f);
  EXPECT_EQ(out.behaviour.request.leds.chest, 0x0000ff);
  ASSERT_EQ(out.receiver.messages.size(), 2u);
  EXPECT_EQ(out.receiver.messages[0].playerNumber, 2);
  EXPECT_EQ(out.receiver.messages[0].utime, 1200000);
  EXPECT_EQ(out.receiver.messages[0].data, (std::vector<uint8_t>{1, 2, 3}));
}

// A snapshot read from a log or the bus is input like any message: out of range is an error,
// not an enum value no behaviour knows or a NaN in the Blackboard.
TEST(Snapshot, FieldsOutOfRangeAreMalformed) {
  const auto rejected = [](const char* why, auto change) {
    blackboard_snapshot_t msg = transport::to_snapshot(sample(), {1, 3}, 37);
    change(msg);
    EXPECT_THROW(transport::from_snapshot(msg), transport::MalformedMessage) << why;
  };
  rejected("team 2", [](blackboard_snapshot_t& m) { m.team = 2; });
  rejected("negative frame", [](blackboard_snapshot_t& m) { m.frame = -1; });
  rejected("unknown action type", [](blackboard_snapshot_t& m) { m.request_body.action_type = 10; });
  rejected("a third foot", [](blackboard_snapshot_t& m) { m.active.foot = 2; });
  rejected("unknown game state", [](blackboard_snapshot_t& m) { m.game_state = 6; });
  rejected("player number 0", [](blackboard_snapshot_t& m) { m.player_number = 0; });
  rejected("a drop-in by team 2", [](blackboard_snapshot_t& m) { m.drop_in_team = 2; });
  rejected("a drop-in time below -1", [](blackboard_snapshot_t& m) { m.drop_in_time = -2; });
  rejected("kick phase 4", [](blackboard_snapshot_t& m) { m.kick_phase = 4; });
  rejected("NaN odometry", [](blackboard_snapshot_t& m) { m.odometry.x_mm = std::nanf(""); });
  rejected("infinite head request", [](blackboard_snapshot_t& m) { m.request_head.yaw_rad = INFINITY; });
  rejected("a message from player 8", [](blackboard_snapshot_t& m) { m.messages[0].player = 8; });
  rejected("negative ball lost count", [](blackboard_snapshot_t& m) { m.ball_lost_count = -1; });
  rejected("NaN sonar", [](blackboard_snapshot_t& m) { m.sonar_left = std::nanf(""); });
  rejected("a seen ball among the robots", [](blackboard_snapshot_t& m) { m.seen_robots[0].kind = 0; });
  rejected("a seen robot number 0", [](blackboard_snapshot_t& m) { m.seen_robots[1].id = 0; });
  rejected("a seen robot at infinity", [](blackboard_snapshot_t& m) { m.seen_robots[0].distance_mm = INFINITY; });
}

TEST(Snapshot, ChannelNamesTheRobot) {
  EXPECT_EQ(transport::snapshot_channel({0, 4}), "TL_BLACKBOARD_0_4");
}
