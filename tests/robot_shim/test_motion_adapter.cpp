#include "touchline/robot/motion_adapter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

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

// Placed mid-step (RobotSense::placed), our walk stands square where it is: the next tick
// moves no foot, and its odometry goes on from where it was (no jump for localisation).
TEST(MotionAdapter, PlacedStandsTheWalkSquareWithoutAJump) {
  robot::MotionAdapter motion(walk_def());
  Blackboard blackboard;
  blackboard.behaviour.request.body = ActionCommand::walk(200, 0, 0.5f);
  for (int i = 0; i < 37; ++i) motion.tick(blackboard);
  ASSERT_FALSE(motion.walk().standing());
  const Pose2D body = motion.walk().odometry();
  motion.placed();
  EXPECT_TRUE(motion.walk().standing());
  EXPECT_NEAR(motion.walk().odometry().x_mm, body.x_mm, 1e-3f);
  EXPECT_NEAR(motion.walk().odometry().theta_rad, body.theta_rad, 1e-5f);
  blackboard.behaviour.request.body = ActionCommand::stand();
  const auto tick = motion.tick(blackboard);
  for (const FootMotion& m : {tick.left, tick.right}) {
    EXPECT_EQ(m.dx_mm, 0.f);
    EXPECT_EQ(m.dy_mm, 0.f);
    EXPECT_EQ(m.dtheta_rad, 0.f);
  }
  EXPECT_NEAR(blackboard.motion.odometry.x, body.x_mm, 1e-3f);
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

// ---- The walk-engine seam --------------------------------------------------------------

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "touchline/robot/nao/leg_kinematics.hpp"
#include "touchline/robot/walk_engine.hpp"

namespace {

/// A feet engine with rUNSWift's V6 period, 12.2 ms: the left foot slides forward at a
/// constant 100 mm/s from the first tick on.
class SlidingFootEngine : public robot::WalkEngine {
 public:
  std::string name() const override { return "sliding"; }
  int64_t period_us() const override { return 12200; }
  robot::EngineOutputKind output_kind() const override { return robot::EngineOutputKind::kFeet; }
  void start(robot::WalkEngineOutput& out) override { fill(out); }
  void tick(const ActionCommand::Body&, const robot::nao::Sensors&, robot::WalkEngineOutput& out) override {
    ++ticks_;
    fill(out);
  }
  robot::WalkEngineStatus status() const override { return {}; }

 private:
  void fill(robot::WalkEngineOutput& out) const {
    const float x = 100.f * static_cast<float>(ticks_) * 0.0122f;
    out.feet = {{x, 50, 0}, {0, -50, 0}};
    out.odometry = {x / 2, 0, 0};
  }
  int64_t ticks_ = 0;
};

/// A joint engine whose every tick is whatever `joints` gives for that tick.
class ScriptedJointEngine : public robot::WalkEngine {
 public:
  using Script = std::function<robot::nao::JointAngles(int64_t tick)>;
  explicit ScriptedJointEngine(Script script, int64_t period_us = 10000) : script_(std::move(script)), period_us_(period_us) {}
  std::string name() const override { return "scripted"; }
  int64_t period_us() const override { return period_us_; }
  robot::EngineOutputKind output_kind() const override { return robot::EngineOutputKind::kJoints; }
  void start(robot::WalkEngineOutput& out) override { out.joints = script_(0); }
  void tick(const ActionCommand::Body&, const robot::nao::Sensors&, robot::WalkEngineOutput& out) override {
    out.joints = script_(++ticks_);
    ++calls;
  }
  robot::WalkEngineStatus status() const override {
    robot::WalkEngineStatus s;
    s.standing = false;
    return s;
  }
  int64_t calls = 0;

 private:
  Script script_;
  int64_t period_us_;
  int64_t ticks_ = 0;
};

/// Standing joints: knees bent a little, soles flat, elbows within range.
robot::nao::JointAngles crouch() {
  robot::nao::JointAngles j{};
  j[robot::nao::kLElbowRoll] = -0.1f;
  j[robot::nao::kRElbowRoll] = 0.1f;
  for (auto side : {robot::nao::Side::kLeft, robot::nao::Side::kRight})
    robot::nao::set_leg_joints(j, side, {0, 0, -0.4, 0.8, -0.4, 0});
  return j;
}

robot::MotionDef quiet(std::ostream& warnings) {
  robot::MotionDef def;
  def.warnings = &warnings;
  return def;
}

} // namespace

TEST(MotionAdapterSeam, An12_2MsEngineTicksExactlyAsOftenAsSimulatedTimeAllows) {
  robot::MotionAdapter motion(std::make_unique<SlidingFootEngine>(), robot::MotionDef{});
  Blackboard blackboard;
  for (int world_tick = 1; world_tick <= 1220; ++world_tick) {
    motion.tick(blackboard);
    // The engine runs ahead to the first sample at or after the world tick's end.
    const int64_t now_us = world_tick * kMotionTickUs;
    ASSERT_EQ(motion.engine_ticks(), (now_us + 12199) / 12200) << "at " << now_us << " us";
    if (world_tick == 100) {
      EXPECT_EQ(motion.engine_ticks(), 82); // one second: ceil(1 / 0.0122)
    }
  }
  EXPECT_EQ(motion.engine_ticks(), 1000); // 12.2 s: exactly 1000 periods, no drift
}

TEST(MotionAdapterSeam, FeetMoveContinuouslyBetweenTheEnginesSamples) {
  robot::MotionAdapter motion(std::make_unique<SlidingFootEngine>(), robot::MotionDef{});
  Blackboard blackboard;
  float travelled = 0;
  for (int i = 0; i < 300; ++i) {
    const TickMotion tick = motion.tick(blackboard);
    // 100 mm/s over every 10 ms world tick, whichever engine samples fall inside it.
    EXPECT_NEAR(tick.left.dx_mm, 1.f, 1e-3f) << "world tick " << i;
    EXPECT_EQ(tick.right.dx_mm, 0.f);
    travelled += tick.left.dx_mm;
  }
  EXPECT_NEAR(travelled, 300.f, 0.05f);
  EXPECT_NEAR(motion.feet().left.x_mm, 300.f, 0.05f);
  EXPECT_NEAR(blackboard.motion.odometry.x, 150.f, 0.05f);
}

TEST(MotionAdapterSeam, AJointEngineIsGivenItsLastCommandAndThePressureOfTheStanceSole) {
  std::ostringstream warnings;
  robot::MotionAdapter motion(std::make_unique<ScriptedJointEngine>([](int64_t) { return crouch(); }), quiet(warnings));
  Blackboard blackboard;
  motion.tick(blackboard);
  EXPECT_EQ(motion.sensors().joints, crouch());
  float left = 0, right = 0;
  for (int i = 0; i < 4; ++i) left += motion.sensors().fsr_kg[static_cast<size_t>(i)];
  for (int i = 4; i < 8; ++i) right += motion.sensors().fsr_kg[static_cast<size_t>(i)];
  EXPECT_GT(left, 5.f);
  EXPECT_EQ(right, 0.f);
  EXPECT_EQ(warnings.str(), "");
}

TEST(MotionAdapterSeam, AJointMovesNoFasterThanItsMotorWhateverTheEngineAsks) {
  std::ostringstream warnings;
  auto script = [](int64_t tick) {
    robot::nao::JointAngles j = crouch();
    if (tick >= 10) j[robot::nao::kLKneePitch] += 1.f; // a whole radian at once
    return j;
  };
  robot::MotionAdapter motion(std::make_unique<ScriptedJointEngine>(script), quiet(warnings));
  Blackboard blackboard;
  for (int i = 0; i < 10; ++i) motion.tick(blackboard); // the engine's 10th tick asks for the jump
  const float step = robot::nao::joint_max_speed_rad_s(robot::nao::kLKneePitch) * 0.01f;
  EXPECT_NEAR(motion.sensors().joints[robot::nao::kLKneePitch], crouch()[robot::nao::kLKneePitch] + step, 1e-5f);
  for (int i = 0; i < 50; ++i) motion.tick(blackboard); // half a second: it has arrived
  EXPECT_NEAR(motion.sensors().joints[robot::nao::kLKneePitch], crouch()[robot::nao::kLKneePitch] + 1.f, 1e-5f);
  EXPECT_EQ(warnings.str(), "");
}

TEST(MotionAdapterSeam, FeetNeverPartFurtherThanANaosLegsReach) {
  // Whatever joints an engine commands within their ranges, the feet stay within two legs'
  // length plus the hips' spacing of each other.
  std::mt19937 random(3);
  auto joints = [&](int64_t) {
    robot::nao::JointAngles j = crouch();
    for (int joint = robot::nao::kLHipYawPitch; joint <= robot::nao::kRAnkleRoll; ++joint) {
      const auto range = robot::nao::joint_range(joint);
      j[static_cast<size_t>(joint)] = std::uniform_real_distribution<float>(range.min_rad, range.max_rad)(random);
    }
    return j;
  };
  std::ostringstream warnings;
  robot::MotionAdapter motion(std::make_unique<ScriptedJointEngine>(joints, 12200), quiet(warnings));
  Blackboard blackboard;
  const robot::nao::LegDimensions legs;
  const double reach_mm = 2 * legs.hip_offset_y_mm + 2 * (legs.thigh_mm + legs.tibia_mm);
  float widest = 0;
  for (int i = 0; i < 3000; ++i) {
    motion.tick(blackboard);
    const auto& f = motion.feet();
    widest = std::max(widest, std::hypot(f.left.x_mm - f.right.x_mm, f.left.y_mm - f.right.y_mm));
  }
  EXPECT_LE(widest, reach_mm);
  EXPECT_GT(widest, 150.f); // random legs do spread
  EXPECT_EQ(warnings.str(), "");
}

TEST(MotionAdapterSeam, ANaNJointStopsTheEngineTheRobotStandsAndOneWarningNamesTheJoint) {
  std::ostringstream warnings;
  auto script = [](int64_t tick) {
    robot::nao::JointAngles j = crouch();
    j[robot::nao::kLHipPitch] += 0.1f * std::sin(static_cast<float>(tick) * 0.1f); // moving
    if (tick >= 50) j[robot::nao::kLKneePitch] = std::numeric_limits<float>::quiet_NaN();
    return j;
  };
  auto engine = std::make_unique<ScriptedJointEngine>(script);
  const ScriptedJointEngine& seen = *engine;
  robot::MotionAdapter motion(std::move(engine), quiet(warnings));
  Blackboard blackboard;
  for (int i = 0; i < 49; ++i) motion.tick(blackboard);
  EXPECT_FALSE(motion.engine_stopped());
  for (int i = 0; i < 200; ++i) {
    const TickMotion tick = motion.tick(blackboard);
    if (i == 0) continue; // the tick of the bad sample still moves to the last good one
    EXPECT_EQ(tick.left.dx_mm, 0.f);
    EXPECT_EQ(tick.right.dx_mm, 0.f);
    EXPECT_EQ(tick.left.dtheta_rad, 0.f);
  }
  EXPECT_TRUE(motion.engine_stopped());
  EXPECT_TRUE(blackboard.motion.standing);
  EXPECT_EQ(seen.calls, 50); // not ticked again
  const std::string text = warnings.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_NE(text.find("LKneePitch = nan"), std::string::npos) << text;
  EXPECT_NE(text.find("scripted"), std::string::npos) << text;
}

TEST(MotionAdapterSeam, AJointOutOfItsRangeStopsTheEngineToo) {
  std::ostringstream warnings;
  auto script = [](int64_t tick) {
    robot::nao::JointAngles j = crouch();
    if (tick >= 10) j[robot::nao::kRAnkleRoll] = 1.5f; // far past 22.8 degrees
    return j;
  };
  robot::MotionAdapter motion(std::make_unique<ScriptedJointEngine>(script), quiet(warnings));
  Blackboard blackboard;
  for (int i = 0; i < 100; ++i) motion.tick(blackboard);
  EXPECT_TRUE(motion.engine_stopped());
  EXPECT_EQ(warnings.str().rfind("walk engine scripted: RAnkleRoll = 1.5 ", 0), 0u) << warnings.str();
}
