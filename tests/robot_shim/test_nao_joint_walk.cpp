// Our joint-space walk through the whole seam: plan -> inverse kinematics -> joints ->
// forward kinematics -> stance-fixed projection -> the world's feet. A walk command of
// N mm/s must move the robot N mm/s.
#include "touchline/robot/nao_joint_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <sstream>

#include "touchline/angles.hpp"
#include "touchline/robot/motion_adapter.hpp"
#include "touchline/robot/walk_engines.hpp"

using namespace touchline;
using namespace touchline::robot;

namespace {

/// The body's mean velocity from t0_s to t1_s of a walk at `body`, in the frame the walk
/// started in (forward mm/s, left mm/s, turn rad/s), through the MotionAdapter.
struct Velocity {
  double forward, left, turn;
};

Velocity measure(const api::ActionCommand::Body& body, int64_t period_us, double t0_s = 3, double t1_s = 7) {
  WalkEngineDef engine;
  engine.name = "nao-joints";
  engine.nao_joints.period_us = period_us;
  std::ostringstream warnings;
  MotionDef def;
  def.warnings = &warnings;
  MotionAdapter motion(make_walk_engine(engine, WalkDef{}, KickDef{}), def);
  api::Blackboard blackboard;
  blackboard.behaviour.request.body = body;
  api::AbsCoord start;
  double heading = 0; // unwrapped
  double heading_at_start = 0;
  float last_theta = 0;
  const int t0 = static_cast<int>(std::lround(t0_s * 100)), t1 = static_cast<int>(std::lround(t1_s * 100));
  for (int tick = 1; tick <= t1; ++tick) {
    motion.tick(blackboard);
    heading += normalise_angle(blackboard.motion.odometry.theta - last_theta);
    last_theta = blackboard.motion.odometry.theta;
    if (tick == t0) {
      start = blackboard.motion.odometry;
      heading_at_start = heading;
    }
  }
  EXPECT_EQ(warnings.str(), "");
  const double span = t1_s - t0_s;
  const auto& end = blackboard.motion.odometry;
  return {(end.x - start.x) / span, (end.y - start.y) / span, (heading - heading_at_start) / span};
}

} // namespace

TEST(NaoJointWalk, ForwardRequestsMoveTheRobotAtTheRequestedSpeed) {
  for (float speed : {100.f, 200.f, 300.f}) {
    const Velocity v = measure(api::ActionCommand::walk(speed, 0, 0), 10000);
    EXPECT_NEAR(v.forward, speed, 0.02 * speed) << speed << " mm/s";
    EXPECT_NEAR(v.left, 0, 2);
  }
}

TEST(NaoJointWalk, SidewaysRequestsMoveTheRobotSideways) {
  for (float speed : {-150.f, 100.f}) {
    const Velocity v = measure(api::ActionCommand::walk(0, speed, 0), 10000);
    EXPECT_NEAR(v.left, speed, 0.03 * std::abs(speed)) << speed << " mm/s";
    EXPECT_NEAR(v.forward, 0, 2);
  }
}

TEST(NaoJointWalk, TurnRequestsTurnTheRobot) {
  for (float turn : {0.5f, -1.0f}) {
    const Velocity v = measure(api::ActionCommand::walk(0, 0, turn), 10000);
    EXPECT_NEAR(v.turn, turn, 0.03 * std::abs(turn)) << turn << " rad/s";
  }
}

TEST(NaoJointWalk, AtANaoV6Period12MsItWalksAsFast) {
  const Velocity v = measure(api::ActionCommand::walk(200, 0, 0), 12000);
  EXPECT_NEAR(v.forward, 200, 4);
}

TEST(NaoJointWalk, ItsJointsStayWithinTheirRangesAtTheWalksLimits) {
  NaoJointWalk walk(NaoJointWalkDef{}, WalkDef{}, KickDef{});
  WalkEngineOutput out;
  walk.start(out);
  EXPECT_FALSE(nao::check_joints(out.joints, 0));
  const api::ActionCommand::Body requests[] = {api::ActionCommand::walk(300, 200, 1.5f),
                                               api::ActionCommand::walk(-200, -200, -1.5f),
                                               api::ActionCommand::walk(300, 0, 0)};
  for (const auto& body : requests)
    for (int i = 0; i < 300; ++i) {
      walk.tick(body, nao::Sensors{}, out);
      const auto fault = nao::check_joints(out.joints, 0);
      ASSERT_FALSE(fault) << *fault;
    }
}

TEST(NaoJointWalk, TheSwingFootLiftsToItsSwingHeightMidStep) {
  NaoJointWalkDef def;
  def.swing_height_mm = 25;
  NaoJointWalk walk(def, WalkDef{}, KickDef{});
  WalkEngineOutput out;
  walk.start(out);
  float highest = 0;
  for (int i = 0; i < 100; ++i) {
    walk.tick(api::ActionCommand::walk(200, 0, 0), nao::Sensors{}, out);
    highest = std::max(highest, walk.swing_lift_mm());
  }
  EXPECT_NEAR(highest, 25.f, 0.5f);
  EXPECT_EQ(walk.name(), "nao-joints");
}

TEST(NaoJointWalk, ItKicksAsTheWalkCycleDoesWhicheverFootBoreTheWeight) {
  // Walk, then kick with either foot: the feet the world gets through the joints match the
  // walkcycle engine's (same plan): the kicking foot swings, the support foot stays.
  for (auto foot : {api::ActionCommand::Foot::LEFT, api::ActionCommand::Foot::RIGHT}) {
    WalkEngineDef joints_def;
    joints_def.name = "nao-joints";
    std::ostringstream warnings;
    MotionDef def;
    def.warnings = &warnings;
    MotionAdapter joints(make_walk_engine(joints_def, WalkDef{}, KickDef{}), def);
    MotionAdapter feet(WalkDef{});
    api::Blackboard a, b;
    a.behaviour.request.body = b.behaviour.request.body = api::ActionCommand::walk(150, 0, 0);
    float worst_mm = 0, kick_travel_mm = 0;
    for (int i = 0; i < 400; ++i) {
      if (i == 130) {
        api::ActionCommand::Body kick;
        kick.actionType = api::ActionCommand::ActionType::KICK;
        kick.power = 1;
        kick.foot = foot;
        a.behaviour.request.body = b.behaviour.request.body = kick;
      }
      joints.tick(a);
      const TickMotion tb = feet.tick(b);
      if (a.motion.kickPhase == 2) kick_travel_mm += std::abs(foot == api::ActionCommand::Foot::LEFT ? tb.left.dx_mm : tb.right.dx_mm);
      for (auto [p, q] : {std::pair{joints.feet().left, feet.feet().left}, std::pair{joints.feet().right, feet.feet().right}})
        worst_mm = std::max(worst_mm, std::hypot(p.x_mm - q.x_mm, p.y_mm - q.y_mm));
      EXPECT_EQ(a.motion.kickPhase, b.motion.kickPhase);
    }
    EXPECT_GT(kick_travel_mm, 200.f); // the swing did happen: back, through, back again
    EXPECT_LT(worst_mm, 1.f);
    EXPECT_EQ(warnings.str(), "");
  }
}

TEST(NaoJointWalk, ADiveRequestStandsForFeetTheLegsCannotReach) {
  // Feet half a metre apart sideways have no leg pose: this engine stands through a dive
  // request (no warning, the engine keeps running) and walks on afterwards.
  WalkEngineDef joints_def;
  joints_def.name = "nao-joints";
  std::ostringstream warnings;
  MotionDef def;
  def.warnings = &warnings;
  MotionAdapter motion(make_walk_engine(joints_def, WalkDef{}, KickDef{}), def);
  api::Blackboard blackboard;
  blackboard.behaviour.request.body.actionType = api::ActionCommand::ActionType::GOALIE_DIVE_LEFT;
  for (int i = 0; i < 100; ++i) motion.tick(blackboard);
  EXPECT_FALSE(motion.engine_stopped());
  EXPECT_TRUE(blackboard.motion.standing);
  EXPECT_NEAR(blackboard.motion.odometry.y, 0.f, 1.f);
  blackboard.behaviour.request.body = api::ActionCommand::walk(200, 0, 0);
  for (int i = 0; i < 100; ++i) motion.tick(blackboard);
  EXPECT_GT(blackboard.motion.odometry.x, 50.f);
  EXPECT_EQ(warnings.str(), "");
}
