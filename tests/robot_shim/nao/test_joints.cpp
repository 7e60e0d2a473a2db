#include "touchline/robot/nao/joints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace touchline::robot::nao;

TEST(NaoJoints, NamesFollowTheV6Order) {
  EXPECT_STREQ(joint_name(kHeadYaw), "HeadYaw");
  EXPECT_STREQ(joint_name(kLHipYawPitch), "LHipYawPitch");
  EXPECT_STREQ(joint_name(kRHipRoll), "RHipRoll");
  EXPECT_STREQ(joint_name(kRHand), "RHand");
  EXPECT_EQ(kJointCount, 25);
  EXPECT_EQ(kRHipRoll, 13);
}

TEST(NaoJoints, ZeroIsWithinRangeExceptWhereTheRangeExcludesIt) {
  JointAngles joints{};
  const auto fault = check_joints(joints, 0.01f);
  ASSERT_TRUE(fault); // the elbows cannot straighten fully: LElbowRoll's range ends at -2 degrees
  EXPECT_EQ(fault->rfind("LElbowRoll = 0 ", 0), 0u) << *fault;
  joints[kLElbowRoll] = -0.1f;
  joints[kRElbowRoll] = 0.1f;
  EXPECT_FALSE(check_joints(joints, 0.01f));
}

TEST(NaoJoints, ANaNOrAnAngleBeyondTheRangeIsNamed) {
  JointAngles joints{};
  joints[kLElbowRoll] = -0.1f;
  joints[kRElbowRoll] = 0.1f;
  joints[kRKneePitch] = std::numeric_limits<float>::quiet_NaN();
  auto fault = check_joints(joints, 0.01f);
  ASSERT_TRUE(fault);
  EXPECT_NE(fault->find("RKneePitch = nan"), std::string::npos) << *fault;
  joints[kRKneePitch] = 0.5f;
  const JointRange roll = joint_range(kLAnkleRoll);
  joints[kLAnkleRoll] = roll.max_rad + 0.005f; // within the tolerance
  EXPECT_FALSE(check_joints(joints, 0.01f));
  joints[kLAnkleRoll] = roll.max_rad + 0.02f;
  fault = check_joints(joints, 0.01f);
  ASSERT_TRUE(fault);
  EXPECT_EQ(fault->rfind("LAnkleRoll", 0), 0u) << *fault;
}
