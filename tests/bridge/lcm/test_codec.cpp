#include "touchline/lcm/codec.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "touchline/join_reply_t.hpp"

using namespace touchline;
using transport::MalformedMessage;

namespace {

template <typename Msg>
std::vector<uint8_t> encode(const Msg& msg) {
  std::vector<uint8_t> bytes(static_cast<size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

RobotAct sample_act() {
  RobotAct act;
  act.id = {1, 3};
  act.frame = 42;
  act.motion_ticks = 4;
  for (int i = 0; i < 4; ++i) {
    act.ticks[i].left = {1.5f * static_cast<float>(i), -0.5f, 0.01f};
    act.ticks[i].right = {2.f, 0.25f * static_cast<float>(i), -0.02f};
  }
  act.head_yaw_rad = 0.3f;
  act.head_pitch_rad = -0.1f;
  act.leds = 0x123456;
  act.behaviour_cpu_us = 1234;
  act.localised_cov_mm2 = {2500, -40, 900};
  act.ball_x_mm = -750;
  act.ball_y_mm = 120;
  act.ball_lost_frames = 9;
  return act;
}

SenseFrame sample_sense() {
  SenseFrame frame;
  frame.frame = 5;
  frame.utime = frame_start_utime(5);
  frame.motion_ticks = ticks_in_frame(5);
  RobotSense robot;
  robot.id = {0, 2};
  robot.seen.push_back({ObjectKind::kGoalPost, 3, 1500, 0.2f, 0.4f});
  robot.seen.push_back({ObjectKind::kTeammate, 1, 800, -0.5f, 0.9f});
  robot.messages.push_back({1, frame_start_utime(4), {1, 2, 3}});
  frame.robots.push_back(robot);
  return frame;
}

/// Decodes `bytes` as a Msg; the MalformedMessage's text, or "" if it decoded.
template <typename Msg>
std::string decode_error(const std::vector<uint8_t>& bytes) {
  Msg msg;
  try {
    transport::decode(bytes.data(), static_cast<int>(bytes.size()), "CH", msg);
    return "";
  } catch (const MalformedMessage& e) {
    return e.what();
  }
}

/// The same, through from_lcm too.
template <typename Msg>
std::string validation_error(const Msg& msg) {
  try {
    transport::from_lcm(msg);
    return "";
  } catch (const MalformedMessage& e) {
    return e.what();
  }
}

void put_be(std::vector<uint8_t>& bytes, size_t at, int64_t value, int width) {
  for (int i = 0; i < width; ++i)
    bytes[at + static_cast<size_t>(i)] = static_cast<uint8_t>(static_cast<uint64_t>(value) >> (8 * (width - 1 - i)));
}

} // namespace

TEST(Codec, ActSurvivesEncodeAndDecode) {
  const RobotAct in = sample_act();
  const auto bytes = encode(transport::to_lcm(in, 1400000, 77));
  act_t msg;
  transport::decode(bytes.data(), static_cast<int>(bytes.size()), "TL_ACT_1_3", msg);
  EXPECT_EQ(msg.instance, 77);
  EXPECT_EQ(msg.utime, 1400000);
  const RobotAct out = transport::from_lcm(msg);
  EXPECT_EQ(out.id, in.id);
  EXPECT_EQ(out.frame, in.frame);
  ASSERT_EQ(out.motion_ticks, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(out.ticks[i].left.dx_mm, in.ticks[i].left.dx_mm);
    EXPECT_EQ(out.ticks[i].right.dy_mm, in.ticks[i].right.dy_mm);
  }
  EXPECT_EQ(out.leds, in.leds);
  EXPECT_EQ(out.behaviour_cpu_us, 1234);
  EXPECT_EQ(out.localised_cov_mm2, in.localised_cov_mm2); // the belief the viewer draws
  EXPECT_EQ(out.ball_x_mm, in.ball_x_mm);
  EXPECT_EQ(out.ball_y_mm, in.ball_y_mm);
  EXPECT_EQ(out.ball_lost_frames, in.ball_lost_frames);
}

TEST(Codec, SenseSurvivesEncodeAndDecode) {
  SenseFrame in;
  in.utime = frame_start_utime(5);
  in.frame = 5;
  in.motion_ticks = ticks_in_frame(5);
  RobotSense first, second;
  first.id = {0, 1};
  first.truth = {-100, 200, 1.f};
  second.id = {1, 4};
  second.active = false;
  second.truth = {300, -200, -2.f};
  second.touch.front_right = second.touch.back = true;
  second.gyro_turn_rad = -0.125f;
  in.robots = {first, second};
  const auto bytes = encode(transport::to_lcm(in));
  sense_t msg;
  transport::decode(bytes.data(), static_cast<int>(bytes.size()), "TL_SENSE", msg);
  const SenseFrame out = transport::from_lcm(msg);
  EXPECT_EQ(out.frame, 5);
  EXPECT_EQ(out.motion_ticks, 4);
  ASSERT_EQ(out.robots.size(), 2u);
  EXPECT_FALSE(out.find({1, 4})->active);
  EXPECT_EQ(out.find({0, 1})->truth.y_mm, 200);
  EXPECT_FALSE(out.find({0, 1})->touch.any());
  const Touch touch = out.find({1, 4})->touch;
  EXPECT_TRUE(touch.front_right && touch.back);
  EXPECT_FALSE(touch.front_left || touch.left || touch.right);
  EXPECT_EQ(out.find({1, 4})->gyro_turn_rad, -0.125f);
  EXPECT_EQ(out.find({0, 2}), nullptr);
}

TEST(Codec, AGyroTurnThatIsNoAngleIsMalformed) {
  for (const float bad : {std::nanf(""), 3.5f, -3.5f}) {
    sense_t msg = transport::to_lcm(sample_sense());
    ASSERT_FALSE(msg.robots.empty());
    msg.robots[0].gyro_turn_rad = bad;
    try {
      transport::from_lcm(msg);
      FAIL() << "took a gyro turn of " << bad;
    } catch (const MalformedMessage& e) {
      EXPECT_NE(std::string(e.what()).find("gyro_turn_rad"), std::string::npos) << e.what();
    }
  }
}

TEST(Codec, TheGameWithItsSetPlaySurvivesEncodeAndDecode) {
  SenseFrame in = sample_sense();
  in.game.state = GameState::kStandby;
  in.game.set_play = SetPlay::kCornerKick;
  in.game.set_play_team = 1;
  in.game.kickoff_team = 1;
  in.game.score = {{2, 3}};
  in.game.drop_in_team = 1;
  in.game.drop_in_s = 40000; // beyond int16: a whole match without a ball out saturates
  const auto bytes = encode(transport::to_lcm(in));
  sense_t msg;
  transport::decode(bytes.data(), static_cast<int>(bytes.size()), "TL_SENSE", msg);
  const SenseFrame out = transport::from_lcm(msg);
  EXPECT_EQ(out.game.state, GameState::kStandby);
  EXPECT_EQ(out.game.set_play, SetPlay::kCornerKick);
  EXPECT_EQ(out.game.set_play_team, 1);
  EXPECT_EQ(out.game.kickoff_team, 1);
  EXPECT_EQ(out.game.score, (std::array<int, 2>{{2, 3}}));
  EXPECT_EQ(out.game.drop_in_team, 1);
  EXPECT_EQ(out.game.drop_in_s, INT16_MAX);
}

TEST(Codec, NoSetPlayMeansNoSetPlayTeamWhateverTheWriterPutThere) {
  sense_t msg = transport::to_lcm(sample_sense());
  msg.set_play = 0;
  msg.set_play_team = 0; // a writer that left the field at its default
  EXPECT_EQ(transport::from_lcm(msg).game.set_play_team, -1);
}

TEST(Codec, WrongTypeOrTruncatedBytesAreAClearError) {
  const auto bytes = encode(transport::to_lcm(sample_act(), 0, 1));
  sense_t wrong_type;
  try {
    transport::decode(bytes.data(), static_cast<int>(bytes.size()), "TL_SENSE", wrong_type);
    FAIL() << "decoded an act_t as a sense_t";
  } catch (const MalformedMessage& e) {
    EXPECT_NE(std::string(e.what()).find("TL_SENSE: cannot decode as sense_t"), std::string::npos)
        << e.what();
  }
  act_t truncated;
  EXPECT_THROW(transport::decode(bytes.data(), static_cast<int>(bytes.size()) / 2, "TL_ACT_1_3", truncated),
               MalformedMessage);
}

TEST(Codec, OutOfRangeFieldsAreRejected) {
  act_t msg = transport::to_lcm(sample_act(), 0, 1);
  msg.player = 9;
  EXPECT_THROW(transport::from_lcm(msg), MalformedMessage);

  msg = transport::to_lcm(sample_act(), 0, 1);
  msg.left[2].dx_mm = std::nanf("");
  EXPECT_THROW(transport::from_lcm(msg), MalformedMessage);

  SenseFrame frame;
  frame.motion_ticks = 3;
  sense_t sense = transport::to_lcm(frame);
  sense.motion_ticks = 7;
  EXPECT_THROW(transport::from_lcm(sense), MalformedMessage);
}

// Issue #13 item 1: the generated decoder resized its vectors to the count it read, so -1
// became (size_t)-1 and std::length_error escaped through the LCM callback.
TEST(Codec, NegativeArrayCountsAreMalformedNotACrash) {
  act_t act = transport::to_lcm(sample_act(), 0, 1);
  act.motion_ticks = -1;
  act.left.clear();
  act.right.clear();
  EXPECT_NE(decode_error<act_t>(encode(act)), "");

  act = transport::to_lcm(sample_act(), 0, 1);
  auto bytes = encode(act);           // no team message: its int16 size ends the message
  put_be(bytes, bytes.size() - 2, -1, 2);
  EXPECT_NE(decode_error<act_t>(bytes), "");

  sense_t sense = transport::to_lcm(sample_sense());
  sense.robots.clear();
  sense.num_robots = -1;
  EXPECT_NE(decode_error<sense_t>(encode(sense)), "");

  sense = transport::to_lcm(sample_sense());
  sense.robots[0].seen.clear();
  sense.robots[0].num_seen = -1;
  EXPECT_NE(decode_error<sense_t>(encode(sense)), "");

  sense = transport::to_lcm(sample_sense());
  sense.robots[0].messages[0].data.clear();
  sense.robots[0].messages[0].size = -1;
  EXPECT_NE(decode_error<sense_t>(encode(sense)), "");
}

TEST(Codec, StringLengthsBelowOneAreMalformed) {
  join_reply_t reply{};
  reply.reason = "taken";
  const auto good = encode(reply);
  ASSERT_EQ(decode_error<join_reply_t>(good), "");
  const size_t length_at = 8 + 8 + 1 + 1 + 8 + 1; // fingerprint, utime, team, player, instance, accepted
  for (const int32_t length : {0, -1, std::numeric_limits<int32_t>::min()}) {
    auto bytes = good;
    put_be(bytes, length_at, length, 4);
    EXPECT_NE(decode_error<join_reply_t>(bytes), "") << "string length " << length;
  }
}

TEST(Codec, BytesAfterTheMessageAreMalformed) {
  auto bytes = encode(transport::to_lcm(sample_act(), 0, 1));
  bytes.push_back(0);
  EXPECT_NE(decode_error<act_t>(bytes).find("1 bytes after the act_t"), std::string::npos)
      << decode_error<act_t>(bytes);
}

TEST(Codec, DecodingIntoAUsedMessageLeavesNothingBehind) {
  RobotAct with_message = sample_act();
  with_message.team_message = {7, 7, 7};
  act_t msg;
  const auto first = encode(transport::to_lcm(with_message, 0, 1));
  transport::decode(first.data(), static_cast<int>(first.size()), "TL_ACT_1_3", msg);
  const auto second = encode(transport::to_lcm(sample_act(), 0, 1));
  transport::decode(second.data(), static_cast<int>(second.size()), "TL_ACT_1_3", msg);
  EXPECT_TRUE(msg.team_message.empty());
}

TEST(Codec, SenseFieldsOutOfRangeAreRejected) {
  ASSERT_EQ(validation_error(transport::to_lcm(sample_sense())), "");
  const auto rejected = [](const char* why, auto change) {
    sense_t msg = transport::to_lcm(sample_sense());
    change(msg);
    EXPECT_NE(validation_error(msg), "") << why;
  };
  rejected("negative frame", [](sense_t& m) { m.frame = -1; });
  rejected("a frame whose time overflows", [](sense_t& m) { m.frame = int64_t{1} << 62; });
  rejected("ticks that do not match the frame", [](sense_t& m) { m.motion_ticks = 3; });
  rejected("a time that does not match the frame", [](sense_t& m) { m.utime += 1; });
  rejected("a negative score", [](sense_t& m) { m.score[1] = -1; });
  rejected("a game state past STANDBY", [](sense_t& m) { m.game_state = 6; });
  rejected("a set play past the penalty kick", [](sense_t& m) { m.set_play = 6; });
  rejected("a set play nobody takes", [](sense_t& m) { m.set_play = 4; m.set_play_team = -1; });
  rejected("a set play for a third team", [](sense_t& m) { m.set_play = 1; m.set_play_team = 2; });
  rejected("a drop-in by a third team", [](sense_t& m) { m.drop_in_team = 2; m.drop_in_s = 0; });
  rejected("a drop-in before the match", [](sense_t& m) { m.drop_in_s = -2; });
  rejected("a drop-in team without a drop-in", [](sense_t& m) { m.drop_in_team = 0; m.drop_in_s = -1; });
  rejected("the same robot twice", [](sense_t& m) { m.robots.push_back(m.robots[0]); m.num_robots = 2; });
  rejected("a sonar reading beyond its range", [](sense_t& m) { m.robots[0].sonar_left = 1.5f; });
  rejected("a goal post that does not exist", [](sense_t& m) { m.robots[0].seen[0].id = 4; });
  rejected("a teammate numbered 0", [](sense_t& m) { m.robots[0].seen[1].id = 0; });
  rejected("a team message from the future", [](sense_t& m) { m.robots[0].messages[0].sent_utime = m.utime + 1; });
}

TEST(Codec, ActFieldsOutOfRangeAreRejected) {
  ASSERT_EQ(validation_error(transport::to_lcm(sample_act(), 0, 1)), "");
  const auto rejected = [](const char* why, auto change) {
    act_t msg = transport::to_lcm(sample_act(), 0, 1);
    change(msg);
    EXPECT_NE(validation_error(msg), "") << why;
  };
  rejected("negative frame", [](act_t& m) { m.frame = -1; });
  rejected("a frame whose time overflows", [](act_t& m) { m.frame = int64_t{1} << 62; });
  rejected("negative CPU time", [](act_t& m) { m.behaviour_cpu_us = -1; });
}

TEST(Codec, ActChannelNamesTheRobot) {
  EXPECT_EQ(transport::act_channel({1, 4}), "TL_ACT_1_4");
}
