// rUNSWift's own walk behind the seam (built only with -DTOUCHLINE_RUNSWIFT_DIR): it takes
// steps (which needs the foot pressure to switch at touchdown), walks at about what it is
// asked, and never commands a joint out of range.
#include "touchline/robot/runswift_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <utility>

#include "touchline/angles.hpp"
#include "touchline/ini.hpp"
#include "touchline/robot/motion_adapter.hpp"
#include "touchline/robot/walk_engines.hpp"

using namespace touchline;
using namespace touchline::robot;

namespace {
struct Outcome {
  api::AbsCoord start, end;
  int touchdowns = 0;
  std::string warnings;
};

/// A MotionAdapter running their walk, its warnings into `warnings`.
MotionAdapter runswift_motion(std::ostringstream& warnings) {
  WalkEngineDef def;
  def.name = "runswift";
  MotionDef motion_def;
  motion_def.warnings = &warnings;
  return MotionAdapter(make_walk_engine(def, WalkDef{}, KickDef{}), motion_def);
}

Outcome walk(const api::ActionCommand::Body& body, double seconds) {
  std::ostringstream warnings;
  MotionAdapter motion = runswift_motion(warnings);
  api::Blackboard blackboard;
  blackboard.behaviour.request.body = body;
  Outcome run;
  nao::Side stance = motion.stance();
  const int ticks = static_cast<int>(seconds * 100);
  for (int i = 1; i <= ticks; ++i) {
    motion.tick(blackboard);
    if (motion.stance() != stance) ++run.touchdowns;
    stance = motion.stance();
    if (i == ticks / 2) run.start = blackboard.motion.odometry;
  }
  run.end = blackboard.motion.odometry;
  run.warnings = warnings.str();
  return run;
}
} // namespace

TEST(RunswiftWalk, ItRunsAt12_2MsAndIsNamedRunswift) {
  const auto engine = make_runswift_walk({});
  EXPECT_EQ(engine->period_us(), 12200);
  EXPECT_EQ(engine->name(), "runswift");
  EXPECT_EQ(engine->output_kind(), EngineOutputKind::kJoints);
}

TEST(RunswiftWalk, ForwardItStepsOnThePressureAndWalksNearlyAsAsked) {
  const Outcome run = walk(api::ActionCommand::walk(200, 0, 0), 10);
  EXPECT_EQ(run.warnings, "");
  EXPECT_GT(run.touchdowns, 25); // a step about every 0.27 s
  const double speed = (run.end.x - run.start.x) / 5;
  std::cout << "rUNSWift walk at 200 mm/s: " << speed << " mm/s, " << run.touchdowns << " support changes in 10 s\n";
  EXPECT_GT(speed, 150);
  EXPECT_LT(speed, 220);
}

TEST(RunswiftWalk, AnOptionFileThatDoesNotParseIsOneLineNamingIt) {
  const std::string path = ::testing::TempDir() + "bad_runswift.cfg";
  std::ofstream(path) << "[motion]\nKpGyro = not-a-number\n";
  try {
    make_runswift_walk({path});
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
}

TEST(RunswiftWalk, TheirKickSwingsTheKickingFootForward) {
  std::ostringstream warnings;
  MotionAdapter motion = runswift_motion(warnings);
  api::Blackboard blackboard;
  for (int i = 0; i < 200; ++i) motion.tick(blackboard); // crouch, ready
  for (auto foot : {api::ActionCommand::Foot::LEFT, api::ActionCommand::Foot::RIGHT}) {
    blackboard.behaviour.request.body = api::ActionCommand::Body{};
    blackboard.behaviour.request.body.actionType = api::ActionCommand::ActionType::KICK;
    blackboard.behaviour.request.body.power = 1;
    blackboard.behaviour.request.body.foot = foot;
    float reach_mm = 0, fastest_mm_s = 0;
    int kicking_ticks = 0;
    for (int i = 0; i < 400; ++i) {
      const TickMotion tick = motion.tick(blackboard);
      const FeetPose& f = motion.feet();
      const float heading = f.right.theta_rad;
      const float dx = (f.left.x_mm - f.right.x_mm) * std::cos(heading) + (f.left.y_mm - f.right.y_mm) * std::sin(heading);
      reach_mm = std::max(reach_mm, foot == api::ActionCommand::Foot::LEFT ? dx : -dx);
      const FootMotion& m = foot == api::ActionCommand::Foot::LEFT ? tick.left : tick.right;
      fastest_mm_s = std::max(fastest_mm_s, std::hypot(m.dx_mm, m.dy_mm) / 0.01f);
      if (blackboard.motion.kickPhase == 2) ++kicking_ticks;
      if (i > 50 && kicking_ticks > 0 && blackboard.motion.kickPhase == 0) blackboard.behaviour.request.body = api::ActionCommand::Body{};
    }
    std::cout << "rUNSWift kick, " << (foot == api::ActionCommand::Foot::LEFT ? "left" : "right") << ": foot " << reach_mm
              << " mm ahead of the other at most, " << fastest_mm_s << " mm/s at fastest, " << kicking_ticks
              << " ticks kicking\n";
    EXPECT_GT(kicking_ticks, 0);
    EXPECT_GT(reach_mm, 50.f);
  }
  EXPECT_EQ(warnings.str(), "");
}

TEST(RunswiftWalk, ItsOwnOdometryAgreesWithWhatTheFeetDid) {
  // Forward their odometry counts steps as the feet made them; turning it integrates the gyro
  // (times their 1.05), which must therefore be fed in their sense of rotation.
  for (const auto& [body, axis] : {std::pair{api::ActionCommand::walk(200, 0, 0), 0},
                                   std::pair{api::ActionCommand::walk(0, 0, 0.8f), 2}}) {
    WalkEngineDef def;
    def.name = "runswift";
    MotionAdapter motion(make_walk_engine(def, WalkDef{}, KickDef{}), MotionDef{});
    api::Blackboard blackboard;
    blackboard.behaviour.request.body = body;
    double turned = 0;
    float last = 0;
    for (int i = 0; i < 600; ++i) {
      motion.tick(blackboard);
      turned += normalise_angle(blackboard.motion.odometry.theta - last);
      last = blackboard.motion.odometry.theta;
    }
    const Pose2D own = *motion.engine().own_odometry();
    if (axis == 0) {
      EXPECT_NEAR(own.x_mm, blackboard.motion.odometry.x, 0.02 * blackboard.motion.odometry.x);
    } else {
      EXPECT_GT(turned, 3.0);
      EXPECT_NEAR(own.theta_rad, turned, 0.1 * turned);
    }
  }
}
