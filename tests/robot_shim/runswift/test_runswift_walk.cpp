// rUNSWift's walk, built from their clone, driven open loop through our adapter with the
// crude contact model of open_loop_rig.hpp: it crouches, steps on the foot pressure we
// simulate, moves at about the requested speed by its own odometry and by our forward
// kinematics, kicks, stands, and a broken tick holds the last good joints.
#include "touchline/robot/runswift/runswift_walk.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "open_loop_rig.hpp"

namespace touchline::robot::runswift {
namespace {

using nao::WalkCommand;
using testing::OpenLoopRig;
using testing::sole_in_torso;

int ticks_for(double seconds) { return static_cast<int>(std::lround(seconds / testing::kDtS)); }

WalkCommand crouch() {
  WalkCommand c;
  c.kind = WalkCommand::Kind::crouch;
  return c;
}

WalkCommand walk(float forward_mm_s, float left_mm_s = 0, float turn_rad_s = 0) {
  WalkCommand c;
  c.kind = WalkCommand::Kind::walk;
  c.forward_mm_s = forward_mm_s;
  c.left_mm_s = left_mm_s;
  c.turn_rad_s = turn_rad_s;
  return c;
}

void run(OpenLoopRig& rig, const WalkCommand& command, double seconds) {
  for (int i = 0, n = ticks_for(seconds); i < n; ++i) rig.tick(command);
}

TEST(RunswiftWalk, CrouchesLevelAtItsWalkingHipHeight) {
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.5);
  EXPECT_STREQ(engine.walk_option(), "READY");
  const auto l = sole_in_torso(rig.sensors().joint_angles_rad, true);
  const auto r = sole_in_torso(rig.sensors().joint_angles_rad, false);
  // Their walking hip height is 230 mm above the ground: each sole 230 mm below its hip
  // joint, which is 85 mm below the torso's origin. Level and flat if every joint's sign
  // and place came across right.
  EXPECT_NEAR(l.position_mm.z, -315, 3);
  EXPECT_NEAR(r.position_mm.z, -315, 3);
  EXPECT_NEAR(l.position_mm.y, 50, 3);
  EXPECT_NEAR(r.position_mm.y, -50, 3);
  EXPECT_LT(l.tilt_rad, 0.02);
  EXPECT_LT(r.tilt_rad, 0.02);
  EXPECT_EQ(rig.faults, 0);
}

TEST(RunswiftWalk, StepsOnTheSimulatedFootPressureAt200MmS) {
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  const double start_s = rig.time_s;
  run(rig, walk(200), 3.0);
  const double odometry_at_3s = rig.odometry_forward_mm, body_at_3s = rig.body_forward_mm;
  run(rig, walk(200), 4.0);

  EXPECT_EQ(rig.faults, 0);
  EXPECT_STREQ(engine.walk_option(), "WALK");
  // Support switches when the landing foot takes the weight: every 0.25-0.3 s once walking
  // (their half-step period is 0.25 s; the switch waits for the touchdown).
  ASSERT_GE(rig.switch_times_s.size(), 20u);
  EXPECT_LT(rig.switch_times_s.front() - start_s, 0.4);
  for (std::size_t i = 2; i < rig.switch_times_s.size(); ++i) {
    const double period = rig.switch_times_s[i] - rig.switch_times_s[i - 1];
    EXPECT_GE(period, 0.25) << "step " << i;
    EXPECT_LE(period, 0.30) << "step " << i;
  }
  // Roughly the requested speed once the speed has ratcheted up, by its own odometry and by
  // our kinematics from the stance sole, which agree.
  const double odometry_speed = (rig.odometry_forward_mm - odometry_at_3s) / 4.0;
  const double body_speed = (rig.body_forward_mm - body_at_3s) / 4.0;
  EXPECT_GT(odometry_speed, 150);
  EXPECT_LT(odometry_speed, 220);
  EXPECT_NEAR(body_speed, odometry_speed, 0.1 * odometry_speed);
  EXPECT_NEAR(rig.body_left_mm, 0, 20);
  // Walking straight: no hip yaw (the rig's kinematics leaves it out), the swing foot lifted.
  EXPECT_LT(rig.max_abs_hip_yaw_pitch_rad, 1e-4);
  EXPECT_GT(rig.max_swing_height_mm, 5);
  EXPECT_LT(rig.max_swing_height_mm, 40);
}

TEST(RunswiftWalk, WithoutATouchdownInThePressureItDoesNotStepInTime) {
  // The same walk with both soles always loaded alike: the support foot never switches on
  // pressure, only after three half-step periods, when their walk gives up and steps out
  // sideways: the pressure we simulate is what makes it walk.
  RunswiftWalk engine;
  OpenLoopRig rig(engine, /*level_pressure=*/true);
  run(rig, crouch(), 1.0);
  run(rig, walk(200), 4.0);
  ASSERT_GE(rig.switch_times_s.size(), 2u);
  for (std::size_t i = 1; i < rig.switch_times_s.size(); ++i)
    EXPECT_GE(rig.switch_times_s[i] - rig.switch_times_s[i - 1], 0.74);
}

TEST(RunswiftWalk, StandsUpStraightWhenAskedToStand) {
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  run(rig, walk(150), 2.0);
  WalkCommand stand;
  stand.kind = WalkCommand::Kind::stand;
  run(rig, stand, 2.0);
  EXPECT_STREQ(engine.walk_option(), "STAND");
  // Their stand is 248 mm from hip joint to ground: higher than the walking crouch.
  EXPECT_NEAR(sole_in_torso(rig.sensors().joint_angles_rad, true).position_mm.z, -85 - 248, 3);
  EXPECT_NEAR(sole_in_torso(rig.sensors().joint_angles_rad, false).position_mm.z, -85 - 248, 3);
  EXPECT_EQ(rig.faults, 0);
}

TEST(RunswiftWalk, KickSwingsTheKickingFootForward) {
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  WalkCommand kick;
  kick.kind = WalkCommand::Kind::kick;
  kick.kick_foot = WalkCommand::Foot::right;
  kick.ball_x_mm = 180;
  kick.ball_y_mm = -50;
  bool kicked = false;
  double most_ahead_mm = 0;
  for (int i = 0; i < ticks_for(4.0); ++i) {
    rig.tick(kick);
    kicked = kicked || std::string(engine.walk_option()) == "KICK";
    const auto& q = rig.sensors().joint_angles_rad;
    most_ahead_mm = std::fmax(most_ahead_mm, sole_in_torso(q, false).position_mm.x - sole_in_torso(q, true).position_mm.x);
  }
  EXPECT_TRUE(kicked);
  EXPECT_GT(most_ahead_mm, 40) << "the right foot never swung ahead of the left";
  // Their kick swings the right arm up past the shoulder's range, which their pipeline clips:
  // clipped here too, not a fault.
  EXPECT_GT(engine.beyond_limit_rad()[nao::RShoulderPitch], 0.1);
  EXPECT_EQ(rig.faults, 0);
}

/// The fastest any joint target moved in a tick during a right kick, as a multiple of what
/// that joint can do.
double fastest_kick_joint(bool limit_joint_speed) {
  RunswiftWalkDef def;
  def.limit_joint_speed = limit_joint_speed;
  RunswiftWalk engine(def);
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  WalkCommand kick;
  kick.kind = WalkCommand::Kind::kick;
  kick.kick_foot = WalkCommand::Foot::right;
  kick.ball_x_mm = 230;
  kick.ball_y_mm = -60;
  double worst = 0;
  nao::JointArray before = rig.sensors().joint_angles_rad;
  for (int i = 0; i < ticks_for(4.0); ++i) {
    const nao::JointArray now = rig.tick(kick).joint_angles_rad;
    for (std::size_t j = 0; j < nao::kJointCount; ++j)
      worst = std::fmax(worst, std::fabs(now[j] - before[j]) / testing::kDtS / nao::kJointMaxSpeed_rad_s[j]);
    before = now;
  }
  return worst;
}

TEST(RunswiftWalk, NoJointTargetMovesFasterThanTheJointCan) {
  EXPECT_GT(fastest_kick_joint(false), 3.0); // their kick, unclipped
  EXPECT_LE(fastest_kick_joint(true), 1.0 + 1e-4);
}

TEST(RunswiftWalk, ANaNJointHoldsTheLastGoodFrameAndNamesTheJoint) {
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  run(rig, walk(100), 1.0);
  const nao::JointArray good = rig.sensors().joint_angles_rad;
  // A NaN gyro poisons their balance filter, and through it a stance ankle.
  nao::NaoSensorFrame broken = rig.sensors();
  broken.gyro_y_rad_s = std::numeric_limits<float>::quiet_NaN();
  const nao::NaoJointFrame out = engine.step(walk(100), broken);
  EXPECT_TRUE(out.engine_fault);
  EXPECT_EQ(out.joint_angles_rad, good);
  EXPECT_EQ(out.odometry_forward_mm, 0);
  EXPECT_NE(engine.fault_message().find("AnklePitch = nan"), std::string::npos) << engine.fault_message();
  EXPECT_EQ(engine.fault_ticks(), 1);
}

TEST(RunswiftWalk, AJointFarBeyondItsLimitIsAFaultNamingIt) {
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  run(rig, walk(100), 1.0);
  // A torso pitch no robot sends: their angle controller drives the stance hip pitch far
  // past its limit.
  nao::NaoSensorFrame tilted = rig.sensors();
  tilted.angle_y_rad = 10;
  bool faulted = false;
  for (int i = 0; i < 50 && !faulted; ++i) faulted = engine.step(walk(100), tilted).engine_fault;
  ASSERT_TRUE(faulted);
  EXPECT_NE(engine.fault_message().find("HipPitch = "), std::string::npos) << engine.fault_message();
  EXPECT_NE(engine.fault_message().find("(limits "), std::string::npos) << engine.fault_message();
}

TEST(RunswiftWalk, EnginesInOneProcessAreIndependentAndRepeatBitForBit) {
  // Several robots' walks in one process (the in-process match): one engine's ticks between
  // another's change nothing of the other's joints.
  RunswiftWalk alone_engine, twin_engine, other_engine;
  OpenLoopRig alone(alone_engine), twin(twin_engine), other(other_engine);
  for (int i = 0; i < ticks_for(4.0); ++i) {
    const WalkCommand c = i < 80 ? crouch() : walk(250, 0, 0);
    const nao::NaoJointFrame a = alone.tick(c);
    other.tick(i < 40 ? crouch() : walk(-100, 80, 0.5f));
    const nao::NaoJointFrame b = twin.tick(c);
    ASSERT_EQ(a.joint_angles_rad, b.joint_angles_rad) << "tick " << i;
    ASSERT_EQ(a.odometry_forward_mm, b.odometry_forward_mm) << "tick " << i;
  }
}

TEST(RunswiftWalk, ElbowsHeldAtZeroAreClippedIntoTheV6Range) {
  // Their walk holds the elbow rolls at 0, just outside the V6's range; like their own
  // motion pipeline, the adapter clips that rather than calling it a fault.
  RunswiftWalk engine;
  OpenLoopRig rig(engine);
  run(rig, crouch(), 1.0);
  const auto& q = rig.sensors().joint_angles_rad;
  EXPECT_FLOAT_EQ(q[nao::LElbowRoll], nao::kJointLimits[nao::LElbowRoll].max_rad);
  EXPECT_FLOAT_EQ(q[nao::RElbowRoll], nao::kJointLimits[nao::RElbowRoll].min_rad);
  EXPECT_EQ(rig.faults, 0);
}

} // namespace
} // namespace touchline::robot::runswift
