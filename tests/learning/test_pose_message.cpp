#include "touchline/learning/pose_message.hpp"

#include <gtest/gtest.h>

using namespace touchline;
using learning::decode_pose_message;
using learning::encode_pose_message;

TEST(PoseMessage, CarriesAPoseToTheMillimetreAndMilliradian) {
  const auto bytes = encode_pose_message({-4321.4f, 2999.6f, -3.1415f});
  ASSERT_EQ(bytes.size(), learning::kPoseMessageBytes);
  const auto pose = decode_pose_message(bytes);
  ASSERT_TRUE(pose);
  EXPECT_EQ(pose->x, -4321.f);
  EXPECT_EQ(pose->y, 3000.f);
  EXPECT_NEAR(pose->theta, -3.1415f, 6e-4f); // -3141.5 mrad rounds to -3142
}

TEST(PoseMessage, AFarPositionIsHeldAtTheInt16Limit) {
  EXPECT_EQ(decode_pose_message(encode_pose_message({1e6f, -1e6f, 0}))->x, 32767.f);
  EXPECT_EQ(decode_pose_message(encode_pose_message({1e6f, -1e6f, 0}))->y, -32767.f);
}

TEST(PoseMessage, OtherBytesAreNoPose) {
  auto bytes = encode_pose_message({1, 2, 0.5f});
  bytes[0] = 'X';
  EXPECT_FALSE(decode_pose_message(bytes));
  EXPECT_FALSE(decode_pose_message({'T', 'P', 1, 2}));
  EXPECT_FALSE(decode_pose_message({}));
}
