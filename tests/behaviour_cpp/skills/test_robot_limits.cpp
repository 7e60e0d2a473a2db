// robot_limits and camera: the same cases as tests/behaviour_py/test_robot_limits.py.
#include "touchline/behaviour/skills/robot_limits.hpp"

#include <gtest/gtest.h>

#include "touchline/behaviour/skills/camera.hpp"

using namespace touchline::behaviour::skills;

TEST(RobotLimits, AreTheWalkAndHeadLimits) {
  EXPECT_EQ(MAX_FORWARD, 300.f);
  EXPECT_EQ(MAX_BACKWARD, 200.f);
  EXPECT_EQ(MAX_LEFT, 200.f);
  EXPECT_EQ(MAX_TURN, 1.5f);
  EXPECT_EQ(MAX_HEAD_YAW, 2.08f);
  EXPECT_EQ(MIN_HEAD_PITCH, -0.67f);
  EXPECT_EQ(MAX_HEAD_PITCH, 0.51f);
}

TEST(RobotLimits, ClampWalkKeepsDirection) {
  auto expect = [](WalkVelocity v, float forward, float left) {
    EXPECT_NEAR(v.forward, forward, 1e-3f);
    EXPECT_NEAR(v.left, left, 1e-3f);
  };
  expect(clampWalk(100.f, 50.f), 100.f, 50.f);
  expect(clampWalk(600.f, 100.f), 300.f, 50.f);   // forward limit
  expect(clampWalk(-500.f, 100.f), -200.f, 40.f); // backward limit
  expect(clampWalk(100.f, -400.f), 50.f, -200.f); // sideways limit
}

TEST(RobotLimits, ClampTurn) {
  EXPECT_EQ(clampTurn(2.f), 1.5f);
  EXPECT_EQ(clampTurn(-2.f), -1.5f);
  EXPECT_EQ(clampTurn(0.25f), 0.25f);
}

TEST(Camera, VisibleRangeIsTheThesisFormula) {
  EXPECT_NEAR(visibleRange(MAX_HEAD_PITCH), 1000.f, 1e-2f); // fully down
  EXPECT_NEAR(visibleRange(MIN_HEAD_PITCH), 4000.f, 1e-2f); // fully up
  EXPECT_NEAR(visibleRange(-0.08f), 2500.f, 1e-2f);
}

TEST(Camera, PitchToSeeInvertsTheFormulaWithAMargin) {
  EXPECT_NEAR(pitchToSee(1000.f), 0.313333f, 1e-5f);
  EXPECT_NEAR(pitchToSee(2500.f), -0.276667f, 1e-5f);
  EXPECT_NEAR(visibleRange(pitchToSee(1000.f)), 1000.f + CAMERA_RANGE_MARGIN, 1e-2f);
  EXPECT_NEAR(visibleRange(pitchToSee(2500.f)), 2500.f + CAMERA_RANGE_MARGIN, 1e-2f);
}

TEST(Camera, PitchToSeeClampsToTheJointLimits) {
  EXPECT_EQ(pitchToSee(4000.f), MIN_HEAD_PITCH);
  EXPECT_EQ(pitchToSee(0.f), MAX_HEAD_PITCH);
}
