// The rUNSWift profile in a Robot, in process: what it sets up before their behaviour.py is
// imported, a request applied, team messages, and every kind of bad input (no
// behaviour.py, an import error, a missing skill, an exception, a wrong type, an
// impossible value): one line (or one traceback), the robot stands with the error LED,
// keeps answering, and loads the fix.
#include "touchline/python/runswift/profile.hpp"

#include <gtest/gtest.h>
#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "touchline/python/python_behaviour.hpp"
#include "touchline/python/runswift/team_message.hpp"
#include "touchline/robot/robot.hpp"
#include "../embedded_python.hpp"

namespace fs = std::filesystem;
namespace py = pybind11;
using namespace touchline;
using namespace touchline::api;
using touchline::python::kErrorChestLed;
using touchline::python::PythonBehaviour;
using touchline::python::PythonBehaviourDef;

namespace {

using testing_support::count;

// What the profile sets up itself must not come from the user's environment.
[[maybe_unused]] testing::Environment* const kInterpreter = testing::AddGlobalTestEnvironment(
    new testing_support::EmbeddedPython({"RUNSWIFT_CHECKOUT_DIR", "LOG_PATH"}));

const fs::path kFixtures = TOUCHLINE_RUNSWIFT_FIXTURES;
const fs::path kOurBehaviour = TOUCHLINE_RUNSWIFT_BEHAVIOUR;
constexpr int64_t kCheckUs = 250000;

class RunswiftRobot : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::make_temp_dir("touchline-rs");
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

  void start(std::map<std::string, std::string> params = {}) {
    python::runswift::RunswiftDef rs;
    python::runswift::apply_params(params, rs);
    rs.name = "robot 0/2";
    rs.log = &log_;
    rs.field.length_mm = 9000;
    PythonBehaviourDef d;
    d.directory = dir_;
    d.team = 0;
    d.player = 2;
    d.name = "robot 0/2";
    d.log = &log_;
    d.wall_clock_us = [this] { return wall_us_; };
    d.profile = python::runswift::make_profile(rs);
    auto owned = std::make_unique<PythonBehaviour>(std::move(d));
    behaviour_ = owned.get();
    robot::RobotDef def;
    def.id = {0, 2};
    def.behaviour = {"runswift", params, dir_.string()};
    robot_ = std::make_unique<robot::Robot>(def, std::move(owned));
  }

  RobotAct step() {
    SenseFrame frame;
    frame.frame = next_frame_++;
    frame.utime = frame_start_utime(frame.frame);
    frame.motion_ticks = ticks_in_frame(frame.frame);
    frame.game.state = touchline::GameState::kPlaying;
    RobotSense sense = sense_;
    sense.id = {0, 2};
    frame.robots.push_back(sense);
    return robot_->step(frame, frame.robots[0]);
  }
  void let_watcher_look() { wall_us_ += kCheckUs; }

  void expect_error_stand(const RobotAct& act) {
    EXPECT_EQ(robot_->blackboard().behaviour.request.body.actionType, ActionCommand::ActionType::STAND);
    EXPECT_EQ(act.leds, kErrorChestLed);
    EXPECT_FALSE(behaviour_->healthy());
  }
  void expect_walking(const RobotAct& act) {
    EXPECT_EQ(robot_->blackboard().behaviour.request.body.actionType, ActionCommand::ActionType::WALK) << log_.str();
    EXPECT_FLOAT_EQ(robot_->blackboard().behaviour.request.body.forward, 150);
    EXPECT_NE(act.leds, kErrorChestLed);
    EXPECT_TRUE(behaviour_->healthy());
  }

  fs::path dir_;
  std::ostringstream log_;
  int64_t wall_us_ = 1000000;
  int64_t next_frame_ = 0;
  RobotSense sense_;
  PythonBehaviour* behaviour_ = nullptr;
  std::unique_ptr<robot::Robot> robot_;
};

} // namespace

TEST_F(RunswiftRobot, TheirBehaviourFindsItsRootItsRobotModuleAndAHarmlessSimulation) {
  install("probe.py");
  install("simulation.py", "Simulation.py");
  // Set where their code runs on a PC: the profile must take it away from their code.
  py::module_::import("os").attr("environ")["RUNSWIFT_CHECKOUT_DIR"] = "/nowhere";
  start({{"skill", "WalkToPoint"}, {"headskill", "HeadFindBall"}});
  step();
  EXPECT_NE(log_.str().find("RUNSWIFT_CHECKOUT_DIR unset for the behaviour"), std::string::npos) << log_.str();
  const py::dict seen = py::module_::import("sys").attr("modules")["behaviour"].attr("SEEN");
  EXPECT_EQ(seen["behaviour_root"].cast<std::string>(), fs::canonical(dir_).string());
  EXPECT_EQ(seen["path0"].cast<std::string>(), fs::canonical(dir_).string());
  EXPECT_TRUE(seen["checkout"].is_none()); // their Simulation module leaves sys.path alone
  EXPECT_TRUE(fs::is_directory(seen["log_path"].cast<std::string>())); // their Log module writes there
  EXPECT_EQ(seen["robot"].cast<std::string>(), "touchline_runswift_robot");
  EXPECT_TRUE(seen["reduce"].cast<bool>());
  EXPECT_EQ(seen["field_length"].cast<int>(), 9000);
  EXPECT_EQ(seen["skill"].cast<std::string>(), "WalkToPoint");
  EXPECT_EQ(seen["headskill"].cast<std::string>(), "HeadFindBall");
  EXPECT_EQ(seen["timestamp"].cast<int64_t>(), 0);
  EXPECT_TRUE(behaviour_->healthy()) << log_.str();
  robot_.reset(); // the log folder the profile made goes with it
  EXPECT_FALSE(fs::exists(seen["log_path"].cast<std::string>()));
}

TEST_F(RunswiftRobot, TheRequestIsAppliedAndTheSharedDataBroadcastOnceASecond) {
  install("probe.py");
  install("simulation.py", "Simulation.py");
  start();
  int sent = 0;
  for (int i = 0; i < 90; ++i) { // 3 s
    const RobotAct act = step();
    if (!act.team_message.empty()) {
      ++sent;
      const auto broadcast = python::runswift::decode_broadcast(act.team_message);
      ASSERT_TRUE(broadcast);
      EXPECT_EQ(broadcast->data.playerNum, 2);
      EXPECT_TRUE(broadcast->data.behaviourSharedData.playingBall);
    }
  }
  EXPECT_EQ(sent, 3);
}

TEST_F(RunswiftRobot, NoBehaviourPyStandsWithOneLineAndLoadsItWhenItAppears) {
  start();
  expect_error_stand(step());
  expect_error_stand(step());
  EXPECT_EQ(log_.str(), "robot 0/2: no behaviour.py (nor package behaviour/) in " + fs::canonical(dir_).string() +
                            " (standing, chest LED magenta until fixed)\n");
  install("walker.py");
  let_watcher_look();
  expect_walking(step());
  EXPECT_NE(log_.str().find("reloaded behaviour (changed: behaviour.py)"), std::string::npos);
}

TEST_F(RunswiftRobot, AnImportErrorStandsAndTheFixLoads) {
  install("import_error.py");
  start();
  expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "importing behaviour failed"), 1) << log_.str();
  EXPECT_NE(log_.str().find("No module named 'no_such_module_anywhere'"), std::string::npos) << log_.str();
  install("walker.py");
  let_watcher_look();
  expect_walking(step());
}

TEST_F(RunswiftRobot, AMissingSkillIsAnErrorNamingItAndTheRobotStands) {
  fs::copy(kOurBehaviour, dir_, fs::copy_options::recursive);
  start({{"skill", "NoSuchSkill"}, {"headskill", "HeadScan"}});
  for (int i = 0; i < 5; ++i) expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "tick() raised"), 1) << log_.str();
  EXPECT_NE(log_.str().find("ImportError: no body skill 'NoSuchSkill'"), std::string::npos) << log_.str();
}

TEST_F(RunswiftRobot, AnExceptionInTickStandsLogsOnceAndTheFixLoads) {
  install("raises.py");
  start();
  for (int i = 0; i < 5; ++i) expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "ValueError: deliberate failure in tick"), 1) << log_.str();
  install("walker.py");
  let_watcher_look();
  expect_walking(step());
}

TEST_F(RunswiftRobot, ARequestOfTheWrongTypeIsOneLineNamingIt) {
  install("wrong_type.py");
  start();
  for (int i = 0; i < 3; ++i) expect_error_stand(step());
  EXPECT_EQ(log_.str(), "robot 0/2: tick() returned touchline_runswift_robot.All, expected robot.BehaviourRequest "
                        "(standing, chest LED magenta until fixed)\n");
}

TEST_F(RunswiftRobot, AnImpossibleValueIsOneLineNamingTheField) {
  install("bad_value.py");
  start();
  expect_error_stand(step());
  EXPECT_EQ(log_.str(), "robot 0/2: BehaviourRequest.actions.body.turn is nan, not a finite number "
                        "(standing, chest LED magenta until fixed)\n");
  install("walker.py");
  let_watcher_look();
  expect_walking(step());
}

TEST_F(RunswiftRobot, AFieldOfTheWrongTypeIsATypeErrorWhereItIsAssigned) {
  install("wrong_field_type.py");
  start();
  expect_error_stand(step());
  EXPECT_EQ(count(log_.str(), "tick() raised"), 1) << log_.str();
  EXPECT_NE(log_.str().find("request.actions = \"walk\""), std::string::npos) << log_.str(); // where
  EXPECT_NE(log_.str().find("TypeError"), std::string::npos) << log_.str();
}

TEST_F(RunswiftRobot, AnUnsimulatedActionStandsWithOneWarningAndNoErrorLed) {
  install("sits.py");
  start();
  for (int i = 0; i < 200; ++i) {
    const RobotAct act = step();
    EXPECT_EQ(robot_->blackboard().behaviour.request.body.actionType, ActionCommand::ActionType::STAND);
    EXPECT_NE(act.leds, kErrorChestLed);
  }
  EXPECT_TRUE(behaviour_->healthy());
  EXPECT_EQ(log_.str(), "robot 0/2: action SIT is not simulated: the robot stands for 3.05 s "
                        "(its duration on the robot)\n");
}

TEST_F(RunswiftRobot, TheirGoalieDiveIsOurDiveWithNoWarning) {
  install("dives.py"); // GOALIE_DIVE_LEFT every frame
  start();
  for (int i = 0; i < 45; ++i) step(); // 1.5 s: down on the left, not yet up (2.4 s)
  const api::MotionBlackboard& motion = robot_->blackboard().motion;
  EXPECT_EQ(robot_->blackboard().behaviour.request.body.actionType, ActionCommand::ActionType::GOALIE_DIVE_LEFT);
  EXPECT_EQ(motion.active.actionType, ActionCommand::ActionType::GOALIE_DIVE_LEFT);
  EXPECT_FALSE(motion.standing);
  EXPECT_NEAR(motion.odometry.y, robot::DiveDef{}.reach_mm, 1.f); // facing +x: left is +y
  EXPECT_NEAR(motion.odometry.x, 0.f, 1.f);
  EXPECT_TRUE(behaviour_->healthy());
  EXPECT_EQ(log_.str(), "");
}

TEST_F(RunswiftRobot, OurTestBehaviourWalksToABallItSees) {
  fs::copy(kOurBehaviour, dir_, fs::copy_options::recursive);
  start({{"skill", "Striker"}, {"headskill", "HeadScan"}});
  sense_.truth = {-1000, 0, 0};
  sense_.seen.push_back({ObjectKind::kBall, 0, 1000, 0, 0.5f}); // 1 m straight ahead
  step();
  EXPECT_TRUE(behaviour_->healthy()) << log_.str();
  const auto& body = robot_->blackboard().behaviour.request.body;
  EXPECT_EQ(body.actionType, ActionCommand::ActionType::WALK) << log_.str();
  EXPECT_GT(body.forward, 100);
  EXPECT_EQ(robot_->blackboard().behaviour.request.leds.chest, 0x00ff00); // ours: green while the ball is seen
}
