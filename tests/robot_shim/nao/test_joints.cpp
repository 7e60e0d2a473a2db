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

TEST(NaoJoints, LegJointsFollowATargetNoFasterThanTheirMotors) {
  // The leg motor: 8000 rpm unloaded, geared 130.85:1 for the pitches, 201.3:1 for the rest.
  EXPECT_NEAR(joint_max_speed_rad_s(kLKneePitch), 6.402f, 0.001f);
  EXPECT_NEAR(joint_max_speed_rad_s(kRAnkleRoll), 4.162f, 0.001f);
  EXPECT_TRUE(std::isinf(joint_max_speed_rad_s(kRShoulderPitch))); // moves no foot
  JointAngles from = clamp_to_ranges(JointAngles{});
  JointAngles target = from;
  target[kLKneePitch] = 1.5f;   // 1.5 rad in one 12.2 ms tick: 123 rad/s asked
  target[kRAnkleRoll] = -0.3f;
  target[kLShoulderPitch] = 1.f;
  const JointAngles at = follow(from, target, 0.0122f);
  EXPECT_NEAR(at[kLKneePitch], 6.402f * 0.0122f, 1e-4f);
  EXPECT_NEAR(at[kRAnkleRoll], -4.162f * 0.0122f, 1e-4f);
  EXPECT_EQ(at[kLShoulderPitch], 1.f);
  // Given time, it gets there, and never beyond its range.
  JointAngles now = from;
  for (int i = 0; i < 100; ++i) now = follow(now, target, 0.0122f);
  EXPECT_EQ(now[kLKneePitch], 1.5f);
  target[kLKneePitch] = 5.f;
  for (int i = 0; i < 100; ++i) now = follow(now, target, 0.0122f);
  EXPECT_EQ(now[kLKneePitch], joint_range(kLKneePitch).max_rad);
}
