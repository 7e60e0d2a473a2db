#include "touchline/robot/motion_adapter.hpp"

#include <gtest/gtest.h>

using namespace touchline;
using namespace touchline::api;

namespace {
robot::WalkDef walk_def() { return robot::WalkDef{}; }
} // namespace

TEST(MotionAdapter, StandRequestKeepsTheFeetStill) {
  robot::MotionAdapter motion(walk_def());
  Blackboard blackboard;
  for (int i = 0; i < 50; ++i) {
    const auto tick = motion.tick(blackboard);
    EXPECT_EQ(tick.left.dx_mm, 0.f);
    EXPECT_EQ(tick.right.dy_mm, 0.f);
  }
  EXPECT_TRUE(blackboard.motion.standing);
  EXPECT_EQ(blackboard.motion.ticks, 50);
}

TEST(MotionAdapter, WalkRequestMovesTheFeetAndTheOdometry) {
  robot::MotionAdapter motion(walk_def());
  Blackboard blackboard;
  blackboard.behaviour.request.body = ActionCommand::walk(200, 0, 0);
  float forward_sum = 0;
  for (int i = 0; i < 200; ++i) {
    const auto tick = motion.tick(blackboard);
    forward_sum += (tick.left.dx_mm + tick.right.dx_mm) / 2;
  }
  EXPECT_FALSE(blackboard.motion.standing);
  EXPECT_GT(blackboard.motion.odometry.x, 250.f); // 2 s at up to 200 mm/s, after the ramp
  EXPECT_NEAR(blackboard.motion.odometry.y, 0.f, 1.f);
  EXPECT_EQ(blackboard.motion.active.actionType, ActionCommand::ActionType::WALK);
  EXPECT_GT(forward_sum, 250.f);
}

TEST(MotionAdapter, SpeedScalesTheWalkRequest) {
  robot::MotionAdapter slow(walk_def()), fast(walk_def());
  Blackboard a, b;
  a.behaviour.request.body = ActionCommand::walk(200, 0, 0);
  a.behaviour.request.body.speed = 0.5f;
  b.behaviour.request.body = ActionCommand::walk(100, 0, 0);
  for (int i = 0; i < 300; ++i) {
    slow.tick(a);
    fast.tick(b);
  }
  EXPECT_FLOAT_EQ(a.motion.odometry.x, b.motion.odometry.x);
}

TEST(MotionAdapter, HeadMovesTowardsTheRequestAtItsSpeedLimitAndStopsAtTheJointLimit) {
  robot::HeadDef head;
  robot::MotionAdapter motion(walk_def(), head);
  Blackboard blackboard;
  blackboard.behaviour.request.head.yaw = 3.f; // beyond the joint limit
  motion.tick(blackboard);
  EXPECT_NEAR(motion.head_yaw(), head.max_speed_rad_s * 0.01f, 1e-6f);
  for (int i = 0; i < 200; ++i) motion.tick(blackboard);
  EXPECT_FLOAT_EQ(motion.head_yaw(), head.max_yaw_rad);
  EXPECT_FLOAT_EQ(blackboard.motion.headYaw, head.max_yaw_rad);
}

TEST(MotionAdapter, ActionsWithoutAGeneratorYetStand) {
  robot::MotionAdapter motion(walk_def());
  Blackboard blackboard;
  // KICK and DRIBBLE have the KickGenerator (test_kick_generator); getting up has none yet.
  blackboard.behaviour.request.body.actionType = ActionCommand::ActionType::GETUP_FRONT;
  for (int i = 0; i < 30; ++i) {
    const auto tick = motion.tick(blackboard);
    EXPECT_EQ(tick.left.dx_mm, 0.f);
  }
}
