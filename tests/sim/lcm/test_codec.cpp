#include "touchline/lcm/codec.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

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
  act.action_type = 2;
  act.leds = 0x123456;
  act.odometry = {10, 20, 0.5f};
  act.behaviour_cpu_us = 1234;
  return act;
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
  EXPECT_EQ(out.odometry.theta_rad, in.odometry.theta_rad);
  EXPECT_EQ(out.behaviour_cpu_us, 1234);
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
  EXPECT_EQ(out.find({0, 2}), nullptr);
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

TEST(Codec, ActChannelNamesTheRobot) {
  EXPECT_EQ(transport::act_channel({1, 4}), "TL_ACT_1_4");
}
