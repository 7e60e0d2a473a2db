// PythonBehaviour in-process: a Robot stepping SenseFrames with a Python module as its
// behaviour (no transport). Each test copies fixture modules (fixtures/) into a temp dir
// of its own, so it can edit them; the wall clock is injected, so reload checks happen
// exactly when a test advances it.
#include "touchline/python/python_behaviour.hpp"

#include <gtest/gtest.h>
#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "embedded_python.hpp"
#include "touchline/robot/robot.hpp"

namespace fs = std::filesystem;
namespace py = pybind11;
using namespace touchline;
using namespace touchline::api;
using touchline::python::kErrorChestLed;
using touchline::python::PythonBehaviour;
using touchline::python::PythonBehaviourDef;
using touchline::python::PythonBehaviourError;

namespace {

using testing_support::count;

// The shim must not write bytecode by itself, whatever the user's environment says.
[[maybe_unused]] testing::Environment* const kInterpreter =
    testing::AddGlobalTestEnvironment(new testing_support::EmbeddedPython({"PYTHONDONTWRITEBYTECODE"}));

const fs::path kFixtures = TOUCHLINE_PY_FIXTURES;
constexpr int64_t kCheckUs = 250000;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Robot 0/2 at (1000, -500) facing +y; the ball 500 mm straight ahead of it.
RobotSense sensing_ball_ahead() {
  RobotSense sense;
  sense.id = {0, 2};
  sense.truth = {1000, -500, kPi / 2};
  sense.ball_x_mm = 1000;
  sense.ball_y_mm = 0;
  sense.seen.push_back({ObjectKind::kBall, 0, 500, 0, 0.5f}); // what the camera reports of it
  return sense;
}

SenseFrame frame_with(RobotSense sense, int64_t frame_index) {
  SenseFrame frame;
  frame.frame = frame_index;
  frame.utime = frame_start_utime(frame_index);
  frame.motion_ticks = ticks_in_frame(frame_index);
  frame.robots.push_back(sense);
  return frame;
}

/// A temp python dir, a captured log, a fake wall clock, and a Robot running the module.
class PythonRobot : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::make_temp_dir("touchline-py");
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    robot_.reset();
    fs::remove_all(dir_);
  }

  /// Copies fixtures/<fixture> to <dir>/<as>, as an edit the watcher sees.
  void install(const std::string& fixture, const std::string& as = "behaviour.py") {
    testing_support::copy_as_edit(kFixtures / fixture, dir_ / as);
  }

  PythonBehaviourDef def(const std::string& module = "behaviour") {
    PythonBehaviourDef d;
    d.directory = dir_;
    d.module = module;
    d.team = 0;
    d.player = 2;
    d.name = "robot 0/2";
    d.log = &log_;
    d.wall_clock_us = [this] { return wall_us_; };
    return d;
  }

  void start(PythonBehaviourDef d) {
    auto owned = std::make_unique<PythonBehaviour>(std::move(d));
    behaviour_ = owned.get();
    robot::RobotDef robot;
    robot.id = {0, 2};
    robot.behaviour = {"py", {}, dir_.string()};
    robot_ = std::make_unique<robot::Robot>(robot, std::move(owned));
  }
  void start() { start(def()); }

  /// Steps the next frame; `sense_` is what the robot senses.
  RobotAct step() {
    const SenseFrame frame = frame_with(sense_, next_frame_++);
    return robot_->step(frame, frame.robots[0]);
  }

  /// Lets the watcher look at the files on the next tick.
  void let_watcher_look() { wall_us_ += kCheckUs; }

  void expect_error_stand(const RobotAct& act) {
    EXPECT_EQ(robot_->blackboard().motion.active.actionType, ActionCommand::ActionType::STAND);
    EXPECT_EQ(act.leds, kErrorChestLed);
    EXPECT_FALSE(behaviour_->healthy());
  }

  void expect_walking(const RobotAct& act, float forward) {
    EXPECT_EQ(robot_->blackboard().motion.active.actionType, ActionCommand::ActionType::WALK);
    EXPECT_NE(act.leds, kErrorChestLed);
    EXPECT_FLOAT_EQ(robot_->blackboard().behaviour.request.body.forward, forward);
    EXPECT_TRUE(behaviour_->healthy());
  }

  /// The module object the behaviour runs (from sys.modules).
  py::object module(const std::string& name = "behaviour") {
    return py::module_::import("sys").attr("modules")[py::str(name)];
  }

  fs::path dir_;
  std::ostringstream log_;
  int64_t wall_us_ = 1000000;
  RobotSense sense_ = sensing_ball_ahead();
  int64_t next_frame_ = 0;
  PythonBehaviour* behaviour_ = nullptr;
  std::unique_ptr<robot::Robot> robot_;
};

TEST_F(PythonRobot, TheModulesWalkBecomesTheRobotsRequest) {
  install("walker.py");
  start();
  const RobotAct act = step();
  expect_walking(act, 150);
  EXPECT_EQ(act.leds, 0x0000ff);
  EXPECT_EQ(robot_->blackboard().behaviour.request.body.actionType, ActionCommand::ActionType::WALK);
  EXPECT_EQ(behaviour_->loads(), 1);
  EXPECT_EQ(log_.str(), "");
}

TEST_F(PythonRobot, PythonSeesWhatTheAdaptersWroteToTheBlackboard) {
  install("probe.py");
  start();
  next_frame_ = 5;
  sense_.touch.right = true; // a robot against the right arm
  step();
  const Blackboard& bb = robot_->blackboard();
  const auto seen = module().attr("SEEN").cast<py::dict>();
  EXPECT_EQ(seen["utime"].cast<int64_t>(), frame_start_utime(5));
  EXPECT_EQ(seen["frame"].cast<int64_t>(), 5);
  const auto pos = seen["robotPos"].cast<std::tuple<float, float, float>>();
  EXPECT_FLOAT_EQ(std::get<0>(pos), 1000);
  EXPECT_FLOAT_EQ(std::get<1>(pos), -500);
  EXPECT_FLOAT_EQ(std::get<2>(pos), kPi / 2);
  const auto ball = seen["ballPosRR"].cast<std::pair<float, float>>();
  EXPECT_FLOAT_EQ(ball.first, bb.localisation.ballPosRR.distance);
  EXPECT_FLOAT_EQ(ball.second, bb.localisation.ballPosRR.heading);
  EXPECT_NEAR(ball.first, 500, 1e-3); // the ball is 500 mm straight ahead of a robot facing +y
  EXPECT_NEAR(ball.second, 0, 1e-6);
  EXPECT_EQ(seen["playerNumber"].cast<int>(), 2);
  EXPECT_EQ(seen["team"].cast<int>(), 0);
  EXPECT_EQ(seen["state"].cast<int>(), static_cast<int>(api::GameState::PLAYING));
  EXPECT_TRUE(seen["ballSeen"].cast<bool>());
  const auto touch = seen["touch"].cast<std::tuple<bool, bool, bool, bool, bool>>();
  EXPECT_EQ(touch, std::make_tuple(false, false, false, true, false)); // front left, front right, left, right, back
  // The behaviour ticks before the frame's motion ticks; none ran before this first frame.
  EXPECT_EQ(seen["motionTicks"].cast<int64_t>(), 0);
  const auto& body = bb.behaviour.request.body;
  EXPECT_FLOAT_EQ(body.forward, 120);
  EXPECT_FLOAT_EQ(body.left, 30);
  EXPECT_FLOAT_EQ(body.turn, 0.2f);
  EXPECT_EQ(bb.behaviour.request.leds.chest, 0x123456);
}

TEST_F(PythonRobot, ParamsTeamAndPlayerReachTheModuleBeforeItIsImported) {
  install("params_probe.py", "behaviour.py");
  auto d = def();
  d.params = {{"forward", "240"}, {"skill", "GoToBall"}};
  d.team = 1;
  d.player = 4;
  start(d);
  expect_walking(step(), 240);
  const auto params = module().attr("PARAMS").cast<std::map<std::string, std::string>>();
  EXPECT_EQ(params, d.params);
  EXPECT_EQ(module().attr("TEAM").cast<int>(), 1);
  EXPECT_EQ(module().attr("PLAYER").cast<int>(), 4);
}

TEST_F(PythonRobot, AMissingModuleIsAOneLineError) {
  install("walker.py");
  try {
    start(def("nonexistent"));
    FAIL() << "no error";
  } catch (const PythonBehaviourError& e) {
    EXPECT_NE(std::string(e.what()).find("no Python module 'nonexistent' in " + fs::canonical(dir_).string()),
              std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

TEST_F(PythonRobot, CheckParamsJudgesTheParamsBeforeTheFirstTick) {
  install("checks_params.py");
  auto d = def();
  d.params = {{"forward", "120"}};
  start(d);
  using Params = std::map<std::string, std::string>;
  const std::vector<Params> checked = module().attr("CHECKED").cast<std::vector<Params>>();
  EXPECT_EQ(checked, std::vector<Params>{d.params});
  expect_walking(step(), 120);
}

TEST_F(PythonRobot, AParameterCheckParamsRefusesIsItsOneLineError) {
  install("checks_params.py");
  auto d = def();
  d.params = {{"speed", "fast"}};
  try {
    start(d);
    FAIL() << "no error";
  } catch (const PythonBehaviourError& e) {
    EXPECT_STREQ(e.what(), "Walker: unknown parameter 'speed'");
  }
  d.params = {{"forward", "quick"}}; // float() raises: its message, whatever the exception
  try {
    start(d);
    FAIL() << "no error";
  } catch (const PythonBehaviourError& e) {
    EXPECT_STREQ(e.what(), "could not convert string to float: 'quick'");
  }
}

TEST_F(PythonRobot, AModuleFromElsewhereOnSysPathIsNotTheBehaviour) {
  // `json` imports fine, but not from the python dir: the behaviour must come from there.
  EXPECT_THROW(start(def("json")), PythonBehaviourError);
}

TEST_F(PythonRobot, AMissingDirectoryIsAnError) {
  auto d = def();
  d.directory = dir_ / "nowhere";
  EXPECT_THROW(start(d), PythonBehaviourError);
}

TEST_F(PythonRobot, AModuleWithoutTickIsAOneLineError) {
  install("no_tick.py");
  try {
    start();
    FAIL() << "no error";
  } catch (const PythonBehaviourError& e) {
    EXPECT_STREQ(e.what(), "Python module 'behaviour' has no tick(blackboard) function");
  }
  EXPECT_EQ(log_.str(), ""); // the error is the exception alone
  // Nothing of the failed behaviour stays loaded: a good module of the same name loads next.
  install("walker.py");
  start();
  expect_walking(step(), 150);
}

TEST_F(PythonRobot, TickThatRaisesStandsWithTheErrorLedAndLogsOnceThenRecoversWhenFixed) {
  install("raises.py");
  start();
  for (int i = 0; i < 60; ++i) expect_error_stand(step());
  const std::string log = log_.str();
  EXPECT_EQ(count(log, "ValueError: deliberate failure in tick at utime 0"), 1) << log;
  EXPECT_EQ(count(log, "Traceback (most recent call last)"), 1) << log;
  EXPECT_NE(log.find("behaviour.py\", line 5, in tick"), std::string::npos) << log;
  for (const auto& line : lines_of(log)) EXPECT_EQ(line.rfind("robot 0/2: ", 0), 0u) << line;

  install("walker.py");
  expect_error_stand(step()); // the wall clock has not moved: nobody looked yet
  let_watcher_look();
  expect_walking(step(), 150);
  expect_walking(step(), 150);
  EXPECT_EQ(count(log_.str(), "robot 0/2: reloaded behaviour (changed: behaviour.py)"), 1) << log_.str();
  EXPECT_EQ(behaviour_->loads(), 2);
}

TEST_F(PythonRobot, SyntaxErrorAtStartStandsAndRecovers) {
  install("syntax_error.py");
  start(); // not a usage error: the shim plays on and waits for the fix
  EXPECT_FALSE(behaviour_->healthy());
  for (int i = 0; i < 30; ++i) expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "SyntaxError"), 1) << log_.str();
  EXPECT_NE(log_.str().find("importing behaviour failed"), std::string::npos) << log_.str();
  EXPECT_EQ(behaviour_->loads(), 0);

  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);
  EXPECT_EQ(count(log_.str(), "reloaded"), 1);
}

TEST_F(PythonRobot, BrokenEditsDuringPlayStandAndLogOncePerChange) {
  install("walker.py");
  start();
  expect_walking(step(), 150);

  install("syntax_error.py");
  let_watcher_look();
  for (int i = 0; i < 30; ++i) {
    expect_error_stand(step());
    let_watcher_look(); // looking again at unchanged files logs nothing new
  }
  EXPECT_EQ(count(log_.str(), "SyntaxError"), 1) << log_.str();

  install("raises_at_import.py"); // a different mistake: a new change, a new report
  let_watcher_look();
  for (int i = 0; i < 30; ++i) expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "RuntimeError: deliberate failure at import"), 1) << log_.str();
  EXPECT_EQ(count(log_.str(), "reloaded"), 0);

  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);
  EXPECT_EQ(count(log_.str(), "reloaded"), 1);
  EXPECT_EQ(count(log_.str(), "SyntaxError"), 1);
}

TEST_F(PythonRobot, WrongReturnTypeStandsWithOneClearLine) {
  install("wrong_type.py");
  start();
  for (int i = 0; i < 30; ++i) expect_error_stand(step());
  const auto lines = lines_of(log_.str());
  ASSERT_EQ(lines.size(), 1u) << log_.str();
  EXPECT_EQ(lines[0], "robot 0/2: tick() returned robot.Body, expected robot.All "
                      "(standing, chest LED magenta until fixed)");
}

TEST_F(PythonRobot, PythonCannotWriteTheBlackboard) {
  install("readonly_probe.py");
  start();
  step();
  const auto results = module().attr("RESULTS").cast<py::dict>();
  for (const char* field : {"utime", "localisation", "playerNumber", "ballLostCount", "request"})
    EXPECT_EQ(results[field].cast<std::string>(), "AttributeError") << field;
  EXPECT_TRUE(results["copy_changed"].cast<bool>());
  const auto after = results["robotPos_after"].cast<std::pair<float, float>>();
  EXPECT_FLOAT_EQ(after.first, 1000); // the nested copies did not write back ...
  EXPECT_FLOAT_EQ(after.second, -500);
  const Blackboard& bb = robot_->blackboard(); // ... and the C++ side is untouched
  EXPECT_EQ(bb.utime, frame_start_utime(0));
  EXPECT_FLOAT_EQ(bb.localisation.robotPos.x, 1000);
  EXPECT_FLOAT_EQ(bb.localisation.robotPos.y, -500);
  EXPECT_EQ(bb.gameController.playerNumber, 2);
  EXPECT_EQ(bb.behaviour.request.body.forward, 0); // what tick returned, not the 999 written
  EXPECT_TRUE(behaviour_->healthy());
}

TEST_F(PythonRobot, EditingAHelperModuleReloadsItToo) {
  install("uses_gait.py");
  install("gait_100.py", "gait.py");
  start();
  expect_walking(step(), 100);
  install("gait_300.py", "gait.py"); // same length as gait_100.py: only the mtime tells
  let_watcher_look();
  expect_walking(step(), 300);
  EXPECT_NE(log_.str().find("reloaded behaviour (changed: gait.py)"), std::string::npos) << log_.str();
  // No bytecode is written: its whole-second mtime check could serve a stale gait.pyc.
  EXPECT_FALSE(fs::exists(dir_ / "__pycache__"));
}

TEST_F(PythonRobot, FilesAreLookedAtOnlyOnceTheCheckIntervalHasPassed) {
  install("walker.py");
  start();
  install("raises.py");
  wall_us_ += kCheckUs - 1;
  expect_walking(step(), 150);
  wall_us_ += 1;
  expect_error_stand(step());
}

TEST_F(PythonRobot, TickRemovedDuringPlayStandsAndSaysSo) {
  install("walker.py");
  start();
  install("no_tick.py");
  let_watcher_look();
  expect_error_stand(step());
  EXPECT_EQ(log_.str(), "robot 0/2: module 'behaviour' has no tick(blackboard) function "
                        "(standing, chest LED magenta until fixed)\n");
}

TEST_F(PythonRobot, AddedAndRemovedFilesAreChanges) {
  install("walker.py");
  start();
  install("gait_100.py", "gait.py");
  let_watcher_look();
  expect_walking(step(), 150);
  EXPECT_EQ(behaviour_->loads(), 2);

  fs::remove(dir_ / "behaviour.py"); // the module itself gone: stand until it is back
  let_watcher_look();
  expect_error_stand(step());
  EXPECT_NE(log_.str().find("ModuleNotFoundError: No module named 'behaviour'"), std::string::npos) << log_.str();
  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);
}

// --- hung Python: the tick guard ----------------------------------------------------------

constexpr int64_t kShortTimeoutUs = 100000; // the bound these tests give a tick

TEST_F(PythonRobot, ATickThatLoopsForeverIsInterruptedThenNotCalledUntilTheFilesChange) {
  install("loops_forever.py");
  auto d = def();
  d.tick_timeout_us = kShortTimeoutUs;
  start(d);
  for (int i = 0; i < 10; ++i) expect_error_stand(step());
  EXPECT_EQ(module().attr("CALLS").cast<int>(), 1); // a hung tick is not tried every frame
  const std::string log = log_.str();
  EXPECT_EQ(count(log, "robot 0/2: tick() timed out, not called again until the files change "
                       "(standing, chest LED magenta until fixed):"), 1) << log;
  EXPECT_EQ(count(log, "touchline.TickTimeout: ran longer than 100 ms of wall time"), 1) << log;
  EXPECT_NE(log.find("behaviour.py\", line 11, in tick"), std::string::npos) << log; // where it hung

  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);
  EXPECT_EQ(count(log_.str(), "robot 0/2: reloaded behaviour (changed: behaviour.py)"), 1) << log_.str();
}

TEST_F(PythonRobot, ATickThatBlocksInACallIsInterruptedToo) {
  install("sleeps_forever.py"); // time.sleep(1e9): no bytecode runs until the call returns
  auto d = def();
  d.tick_timeout_us = kShortTimeoutUs;
  start(d);
  for (int i = 0; i < 3; ++i) expect_error_stand(step());
  EXPECT_EQ(module().attr("CALLS").cast<int>(), 1);
  EXPECT_EQ(count(log_.str(), "touchline.TickTimeout"), 1) << log_.str();
  EXPECT_NE(log_.str().find("time.sleep(1e9)"), std::string::npos) << log_.str();

  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);
}

TEST_F(PythonRobot, AModuleThatHangsAtImportIsInterruptedAndItsFixLoads) {
  install("hangs_at_import.py");
  auto d = def();
  d.tick_timeout_us = kShortTimeoutUs;
  start(d); // not a usage error: the shim plays on, standing, and waits for the fix
  EXPECT_FALSE(behaviour_->healthy());
  expect_error_stand(step());
  EXPECT_NE(log_.str().find("importing behaviour failed"), std::string::npos) << log_.str();
  EXPECT_EQ(count(log_.str(), "touchline.TickTimeout"), 1) << log_.str();

  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);

  install("hangs_at_import.py"); // and the same when an edit during play hangs the reload
  let_watcher_look();
  expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "touchline.TickTimeout"), 2) << log_.str();
  install("walker.py");
  let_watcher_look();
  expect_walking(step(), 150);
}

TEST_F(PythonRobot, ACheckParamsThatHangsIsInterruptedAndIsAOneLineError) {
  install("check_params_loops.py");
  auto d = def();
  d.tick_timeout_us = kShortTimeoutUs;
  try {
    start(d);
    FAIL() << "no error";
  } catch (const PythonBehaviourError& e) {
    EXPECT_STREQ(e.what(), "Python module 'behaviour': check_params() timed out");
  }
}

TEST_F(PythonRobot, TimeTheProcessSpentStoppedDoesNotCount) {
  // 1.4 s in tick(), but a SIGCONT (the process was stopped and continued) 0.7 s in:
  // the 1 s bound counts from there, so the tick finishes.
  install("stopped_midway.py");
  auto d = def();
  d.tick_timeout_us = 1000000;
  start(d);
  expect_walking(step(), 150);
  EXPECT_EQ(log_.str(), "");
}

/// A Python behaviour from `dir` with robot.params {"id": id}: one of several robots in one process.
std::unique_ptr<PythonBehaviour> robot_with_id(const fs::path& dir, const std::string& id) {
  PythonBehaviourDef d;
  d.directory = dir;
  d.params = {{"id", id}};
  return std::make_unique<PythonBehaviour>(d);
}

TEST(PythonBehaviours, TwoInOneProcessKeepTheirOwnModulesAndParams) {
  const fs::path dir = testing_support::make_temp_dir("touchline-py");
  fs::copy_file(kFixtures / "counter.py", dir / "behaviour.py");
  auto make = [&](const std::string& id) { return robot_with_id(dir, id); };
  {
    auto a = make("1");
    auto b = make("2");
    Blackboard bb;
    for (int i = 0; i < 3; ++i) {
      const auto ra = a->tick(bb);
      EXPECT_FLOAT_EQ(ra.body.forward, static_cast<float>(i + 1)); // a's own count
      EXPECT_FLOAT_EQ(ra.body.left, 1);                            // a's own params
    }
    const auto rb = b->tick(bb);
    EXPECT_FLOAT_EQ(rb.body.forward, 1);
    EXPECT_FLOAT_EQ(rb.body.left, 2);
    EXPECT_FLOAT_EQ(a->tick(bb).body.forward, 4);
  }
  fs::remove_all(dir);
}

TEST(PythonBehaviours, AModuleLoadedMidMatchStaysItsRobots) {
  // A helper first imported by a later tick, while the other robot's modules are stashed,
  // is this robot's: swapping the robots looks at what each loaded, not at every module.
  const fs::path dir = testing_support::make_temp_dir("touchline-py");
  fs::copy_file(kFixtures / "lazy_counter.py", dir / "behaviour.py");
  fs::copy_file(kFixtures / "count_helper.py", dir / "count_helper.py");
  auto make = [&](const std::string& id) { return robot_with_id(dir, id); };
  {
    auto a = make("1");
    auto b = make("2");
    Blackboard bb;
    for (int i = 0; i < 4; ++i) { // alternating, as in a match
      EXPECT_FLOAT_EQ(a->tick(bb).body.forward, static_cast<float>(i)) << i;
      EXPECT_FLOAT_EQ(b->tick(bb).body.forward, static_cast<float>(i)) << i;
    }
    EXPECT_FLOAT_EQ(a->tick(bb).body.forward, 4);
  }
  fs::remove_all(dir);
}

TEST(PythonBehaviours, TheErrorRequestStandsWithTheErrorLed) {
  const auto request = touchline::python::error_request();
  EXPECT_EQ(request.body.actionType, ActionCommand::ActionType::STAND);
  EXPECT_EQ(request.leds.chest, 0xff00ff);
}

} // namespace
