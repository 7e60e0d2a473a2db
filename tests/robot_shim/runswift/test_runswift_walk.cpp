// rUNSWift's own walk behind the seam (built only with -DTOUCHLINE_RUNSWIFT_DIR): it takes
// steps (which needs the foot pressure to switch at touchdown), walks at about what it is
// asked, and never commands a joint out of range.
#include "touchline/robot/runswift_walk.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

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

Outcome walk(const api::ActionCommand::Body& body, double seconds) {
  WalkEngineDef def;
  def.name = "runswift";
  std::ostringstream warnings;
  MotionDef motion_def;
  motion_def.warnings = &warnings;
  MotionAdapter motion(make_walk_engine(def, WalkDef{}, KickDef{}), motion_def);
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
