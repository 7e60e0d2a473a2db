// Nao V6 leg kinematics: forward kinematics against poses worked out by hand from the
// published link lengths, and inverse kinematics as its exact inverse.
#include "touchline/robot/nao/leg_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace touchline::robot::nao;

namespace {
constexpr double kStraight_mm = 85 + 100 + 102.9 + 45.19; // torso to sole, legs straight

void expect_near(const Eigen::Vector3d& got, const Eigen::Vector3d& want, double tol = 1e-9) {
  EXPECT_NEAR(got.x(), want.x(), tol);
  EXPECT_NEAR(got.y(), want.y(), tol);
  EXPECT_NEAR(got.z(), want.z(), tol);
}
} // namespace

TEST(LegKinematics, ZeroJointsPutEachSoleStraightBelowItsHipAtTheLegsLength) {
  for (Side side : {Side::kLeft, Side::kRight}) {
    const Eigen::Isometry3d sole = sole_in_torso(side, LegJoints{});
    expect_near(sole.translation(), {0, side == Side::kLeft ? 50.0 : -50.0, -kStraight_mm});
    EXPECT_TRUE(sole.linear().isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  }
  EXPECT_NEAR(LegDimensions{}.straight_leg_mm(), 333.09, 1e-9);
}

TEST(LegKinematics, AKneeBendSwingsShinAndFootBackAboutTheKnee) {
  LegJoints q;
  q.knee_pitch = 0.5;
  const Eigen::Isometry3d sole = sole_in_torso(Side::kLeft, q);
  const double below_knee = 102.9 + 45.19;
  expect_near(sole.translation(), {-below_knee * std::sin(0.5), 50, -85 - 100 - below_knee * std::cos(0.5)});
  EXPECT_NEAR(std::atan2(sole.linear()(0, 2), sole.linear()(2, 2)), 0.5, 1e-12); // the sole pitched with the shin
}

TEST(LegKinematics, ACrouchWithFlatSolesLowersTheSoleStraightDown) {
  // Hip -k/2, knee k, ankle -k/2: thigh and shin make an isosceles-like bend, the sole stays flat.
  LegJoints q;
  q.hip_pitch = -0.4;
  q.knee_pitch = 0.8;
  q.ankle_pitch = -0.4;
  const Eigen::Isometry3d sole = sole_in_torso(Side::kRight, q);
  const double x = 100 * std::sin(0.4) - 102.9 * std::sin(0.4);
  const double z = -85 - 100 * std::cos(0.4) - 102.9 * std::cos(0.4) - 45.19;
  expect_near(sole.translation(), {x, -50, z});
  EXPECT_TRUE(sole.linear().isApprox(Eigen::Matrix3d::Identity(), 1e-12));
}

TEST(LegKinematics, NegativeHipYawPitchTurnsBothToesOutwardAsMirrorImages) {
  LegJoints q;
  q.hip_yaw_pitch = -0.4;
  const Eigen::Isometry3d left = sole_in_torso(Side::kLeft, q);
  const Eigen::Isometry3d right = sole_in_torso(Side::kRight, q);
  EXPECT_GT(yaw_of(left.linear()), 0.2);  // anticlockwise
  EXPECT_NEAR(yaw_of(right.linear()), -yaw_of(left.linear()), 1e-12);
  EXPECT_NEAR(right.translation().x(), left.translation().x(), 1e-9);
  EXPECT_NEAR(right.translation().y(), -left.translation().y(), 1e-9);
  EXPECT_NEAR(right.translation().z(), left.translation().z(), 1e-9);
}

TEST(LegKinematics, InverseKinematicsOfForwardKinematicsGivesTheJointsBack) {
  std::mt19937 random(7);
  auto in = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  for (int i = 0; i < 2000; ++i) {
    const Side side = i % 2 ? Side::kLeft : Side::kRight;
    // Standing and walking poses: the hip above the ankle, the ankle below the hip.
    LegJoints q{in(-0.6, 0.4), in(-0.35, 0.35), in(-0.9, 0.4), in(0.05, 1.6), in(-0.9, 0.6), in(-0.35, 0.35)};
    const Eigen::Isometry3d sole = sole_in_torso(side, q);
    EXPECT_NEAR(hip_yaw_pitch_for(side, sole), q.hip_yaw_pitch, 1e-9);
    const LegJoints back = leg_ik(side, sole, q.hip_yaw_pitch);
    EXPECT_NEAR(back.hip_roll, q.hip_roll, 1e-7);
    EXPECT_NEAR(back.hip_pitch, q.hip_pitch, 1e-7);
    EXPECT_NEAR(back.knee_pitch, q.knee_pitch, 1e-7);
    EXPECT_NEAR(back.ankle_pitch, q.ankle_pitch, 1e-7);
    EXPECT_NEAR(back.ankle_roll, q.ankle_roll, 1e-7);
    if (HasFailure()) break;
  }
}

TEST(LegKinematics, BeyondReachTheLegStraightensTowardsTheTarget) {
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(0, 50, -500); // 500 mm below the torso: 167 mm out of reach
  const LegJoints q = leg_ik(Side::kLeft, far, 0);
  EXPECT_NEAR(q.knee_pitch, 0, 1e-9);
  expect_near(sole_in_torso(Side::kLeft, q).translation(), {0, 50, -kStraight_mm}, 1e-6);
}

TEST(LegKinematics, TheJointsOfOneLegGoToAndComeFromTheirPlacesAmongThe25) {
  JointAngles joints{};
  const LegJoints right{0.1, -0.2, -0.3, 0.4, -0.5, 0.15};
  set_leg_joints(joints, Side::kRight, right);
  EXPECT_FLOAT_EQ(joints[kLHipYawPitch], 0.1f);
  EXPECT_FLOAT_EQ(joints[kRHipRoll], -0.2f);
  EXPECT_FLOAT_EQ(joints[kRKneePitch], 0.4f);
  EXPECT_FLOAT_EQ(joints[kRAnkleRoll], 0.15f);
  EXPECT_EQ(joints[kLKneePitch], 0.f);
  const LegJoints back = leg_joints(joints, Side::kRight);
  EXPECT_NEAR(back.ankle_pitch, -0.5, 1e-7);
  EXPECT_NEAR(leg_joints(joints, Side::kLeft).hip_yaw_pitch, 0.1, 1e-7); // shared
}
