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

TEST(NaoJoints, ArmsBeyondTheirRangesMeetTheirStopsLegsBeyondTheirsAreFaults) {
  JointAngles joints{};
  // The elbows cannot straighten fully (LElbowRoll's range ends at -2 degrees): a walk that
  // leaves the arms at 0 is no fault, the motors stop at the limit.
  EXPECT_FALSE(check_joints(joints, 0.01f));
  const JointAngles clamped = clamp_to_ranges(joints);
  EXPECT_FLOAT_EQ(clamped[kLElbowRoll], joint_range(kLElbowRoll).max_rad);
  EXPECT_FLOAT_EQ(clamped[kRElbowRoll], joint_range(kRElbowRoll).min_rad);
  EXPECT_EQ(clamped[kLKneePitch], 0.f);
  joints[kRKneePitch] = -0.2f; // a knee bent backwards
  const auto fault = check_joints(joints, 0.01f);
  ASSERT_TRUE(fault);
  EXPECT_EQ(fault->rfind("RKneePitch = -0.2 ", 0), 0u) << *fault;
  EXPECT_TRUE(is_leg_joint(kLHipYawPitch) && is_leg_joint(kRAnkleRoll) && !is_leg_joint(kRShoulderPitch));
}

TEST(NaoJoints, ANaNOrAnAngleBeyondTheRangeIsNamed) {
  JointAngles joints{};
  joints[kRShoulderRoll] = std::numeric_limits<float>::quiet_NaN(); // NaN anywhere is a fault
  auto fault = check_joints(joints, 0.01f);
  ASSERT_TRUE(fault);
  EXPECT_NE(fault->find("RShoulderRoll = nan"), std::string::npos) << *fault;
  joints[kRShoulderRoll] = 0;
  joints[kRKneePitch] = std::numeric_limits<float>::quiet_NaN();
  fault = check_joints(joints, 0.01f);
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
