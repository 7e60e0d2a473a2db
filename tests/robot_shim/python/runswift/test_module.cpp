// Their `robot` module as behaviour code sees it: enums that index lists as integers do,
// constructors with their argument order and defaults, read-only blackboards, the field's
// constants from the world config, and the helpers their code calls.
#include "touchline/python/runswift/module.hpp"

#include <gtest/gtest.h>
#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include "touchline/python/runswift/types.hpp"

namespace py = pybind11;
using namespace touchline::python::runswift;

namespace {

class Interpreter : public testing::Environment {
 public:
  void SetUp() override { guard_ = std::make_unique<py::scoped_interpreter>(false, 0, nullptr, false); }
  void TearDown() override { guard_.reset(); }

 private:
  std::unique_ptr<py::scoped_interpreter> guard_;
};
[[maybe_unused]] testing::Environment* const kInterpreter = testing::AddGlobalTestEnvironment(new Interpreter);

/// Runs `code` with `robot` bound to the module; returns the global `result`.
py::object run(const std::string& code) {
  py::dict scope;
  scope["robot"] = py::module_::import(kModuleName);
  py::exec(code, scope);
  return scope.contains("result") ? py::object(scope["result"]) : py::object(py::none());
}

} // namespace

TEST(RobotModule, EnumsAreIntegersThatIndexLists) {
  EXPECT_EQ(run("result = [10, 20, 30][robot.Joints.HeadPitch]").cast<int>(), 20);
  EXPECT_EQ(run("result = int(robot.ActionType.WALK)").cast<int>(), WALK);
  EXPECT_EQ(run("result = int(robot.ActionType.KICK)").cast<int>(), KICK);
  EXPECT_EQ(run("result = int(robot.Foot.RIGHT)").cast<int>(), 1);
  EXPECT_EQ(run("result = int(robot.StiffenCommand.STIFFEN)").cast<int>(), 1);
  EXPECT_EQ(run("result = int(robot.Sensors.SonarLeft)").cast<int>(), SonarLeft);
  EXPECT_EQ(run("result = robot.ActionType.SIGNAL_FULL_TIME.name").cast<std::string>(), "SIGNAL_FULL_TIME");
  EXPECT_TRUE(run("result = not hasattr(robot.ActionType, 'GOALIE_FAST_SIT')").cast<bool>()); // theirs has none
}

TEST(RobotModule, GameControllerConstantsAreTheProtocolsNumbers) {
  EXPECT_EQ(run("result = (robot.STATE_INITIAL, robot.STATE_READY, robot.STATE_SET, robot.STATE_PLAYING, "
                "robot.STATE_FINISHED, robot.STATE_STANDBY)").cast<std::vector<int>>(),
            (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(run("result = (robot.SET_PLAY_NONE, robot.SET_PLAY_GOAL_KICK, robot.SET_PLAY_PUSHING_FREE_KICK, "
                "robot.SET_PLAY_CORNER_KICK, robot.SET_PLAY_KICK_IN, robot.SET_PLAY_PENALTY_KICK)").cast<std::vector<int>>(),
            (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(run("result = (robot.GAME_PHASE_NORMAL, robot.GAME_PHASE_PENALTYSHOOT, robot.GAME_PHASE_OVERTIME, "
                "robot.GAME_PHASE_TIMEOUT)").cast<std::vector<int>>(), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(run("result = (robot.PENALTY_NONE, robot.PENALTY_SPL_PLAYER_PUSHING, robot.PENALTY_SPL_LEAVING_THE_FIELD, "
                "robot.PENALTY_MANUAL)").cast<std::vector<int>>(), (std::vector<int>{0, 2, 6, 15}));
  EXPECT_EQ(run("result = robot.MAX_NUM_PLAYERS").cast<int>(), 7);
}

TEST(RobotModule, BodyCommandTakesTheirThirteenArgumentsInTheirOrder) {
  const py::object body = run(
      "result = robot.BodyCommand(robot.ActionType.KICK, 10, -20, 0.5, 0.8, 0.1, 0.6, robot.Foot.RIGHT, "
      "True, False, True, False, True)");
  const auto& b = body.cast<const BodyCommand&>();
  EXPECT_EQ(b.actionType, KICK);
  EXPECT_EQ(b.forward, 10);
  EXPECT_EQ(b.left, -20);
  EXPECT_FLOAT_EQ(b.turn, 0.5f);
  EXPECT_FLOAT_EQ(b.power, 0.8f);
  EXPECT_FLOAT_EQ(b.bend, 0.1f);
  EXPECT_FLOAT_EQ(b.speed, 0.6f);
  EXPECT_EQ(b.foot, FOOT_RIGHT);
  EXPECT_TRUE(b.useShuffle);
  EXPECT_FALSE(b.leftArmBehind);
  EXPECT_TRUE(b.rightArmBehind);
  EXPECT_TRUE(b.extraStableKick);
  // forward and left are integers there: a float is refused, as their module refuses it
  EXPECT_THROW(run("robot.BodyCommand(robot.ActionType.WALK, 1.5, 0, 0.0, 0.0, 0.0, 1.0, robot.Foot.LEFT, "
                   "False, False, False, False, False)"),
               py::error_already_set);
}

TEST(RobotModule, DefaultsAreTheirs) {
  EXPECT_EQ(run("result = robot.BodyCommand().actionType").cast<int>(), NONE);
  EXPECT_TRUE(run("result = robot.HeadCommand().isRelative").cast<bool>());
  EXPECT_TRUE(run("result = robot.HeadCommand(0.3).isRelative").cast<bool>()); // HeadCommand(yaw) is relative
  EXPECT_FLOAT_EQ(run("result = robot.HeadCommand(0.3).yawSpeed").cast<float>(), 1.f);
  EXPECT_TRUE(run("c = robot.LEDCommand(); result = (c.leftEye.red and c.chestButton.green and not c.leftFoot.red)")
                  .cast<bool>());
  EXPECT_EQ(run("result = robot.LEDCommand().rightEar").cast<int>(), 0x3FF);
  EXPECT_FALSE(run("result = robot.rgb().red").cast<bool>());
  EXPECT_EQ(run("result = robot.All().body.actionType").cast<int>(), NONE);
  EXPECT_EQ(run("result = robot.BehaviourSharedData().secondsSinceLastKick").cast<int>(), -1);
}

TEST(RobotModule, NestedFieldsOfARequestAreWrittenInPlace) {
  const py::object r = run(
      "r = robot.BehaviourRequest()\n"
      "r.actions.leds.chestButton = robot.rgb(True, False, True)\n"
      "r.actions.body.actionType = robot.ActionType.WALK\n"
      "r.actions.body.forward = 120\n"
      "r.actions.head = robot.HeadCommand(0.5, 0.2, False, 0.8, 0.4)\n"
      "r.behaviourSharedData.playingBall = True\n"
      "r.behaviourDebugInfo.bodyBehaviourHierarchy = 'Game.Striker.'\n"
      "result = r");
  const auto& req = r.cast<const BehaviourRequest&>();
  EXPECT_TRUE(req.actions.leds.chestButton.red);
  EXPECT_TRUE(req.actions.leds.chestButton.blue);
  EXPECT_EQ(req.actions.body.actionType, WALK);
  EXPECT_EQ(req.actions.body.forward, 120);
  EXPECT_FALSE(req.actions.head.isRelative);
  EXPECT_FLOAT_EQ(req.actions.head.pitchSpeed, 0.4f);
  EXPECT_TRUE(req.behaviourSharedData.playingBall);
  EXPECT_EQ(req.behaviourDebugInfo.bodyBehaviourHierarchy, "Game.Striker.");
  // a field of the wrong type is a TypeError where it is assigned
  EXPECT_THROW(run("r = robot.BehaviourRequest(); r.actions = 'walk'"), py::error_already_set);
}

TEST(RobotModule, TheBlackboardIsReadOnly) {
  Blackboard bb;
  bb.stateEstimation.robotPos = {100, 200, 0.5f};
  bb.motion.sensors.sensors[SonarLeft] = 0.4f;
  py::dict scope;
  scope["robot"] = py::module_::import(kModuleName);
  scope["bb"] = py::cast(bb);
  py::exec("x = bb.stateEstimation.robotPos.x\n"
           "sonar = robot.floatArray_frompointer(bb.motion.sensors.sensors)[robot.Sensors.SonarLeft]\n",
           scope);
  EXPECT_FLOAT_EQ(scope["x"].cast<float>(), 100);
  EXPECT_FLOAT_EQ(scope["sonar"].cast<float>(), 0.4f);
  EXPECT_THROW(py::exec("bb.stateEstimation.robotPos.x = 5", scope), py::error_already_set);
  EXPECT_THROW(py::exec("bb.stateEstimation = None", scope), py::error_already_set);
  // arrays are copies: writing one does not reach the robot
  py::exec("s = bb.motion.sensors.sensors; s[0] = 99.0; again = bb.motion.sensors.sensors[0]", scope);
  EXPECT_FLOAT_EQ(scope["again"].cast<float>(), 0);
}

TEST(RobotModule, CovariancesAreTuplesOfColumns) {
  py::module_::import(kModuleName); // registers the types
  AbsCoord c;
  c.var = {1, 2, 3, 4, 5, 6, 7, 8, 9}; // row-major
  py::dict scope;
  scope["c"] = py::cast(c);
  py::exec("v = c.var\nfirst_column = v[0]", scope);
  EXPECT_EQ(scope["first_column"].cast<std::vector<float>>(), (std::vector<float>{1, 4, 7}));
}

TEST(RobotModule, FieldConstantsComeFromTheWorldsField) {
  py::module_ m = py::module_::import(kModuleName);
  touchline::robot::localisation::FieldMap f;
  f.length_mm = 9000;
  f.width_mm = 6000;
  f.goal_width_mm = 1500;
  f.goal_box_length_mm = 600;
  f.goal_box_width_mm = 2200;
  f.penalty_area_length_mm = 1650;
  f.penalty_area_width_mm = 4000;
  f.penalty_mark_distance_mm = 1300;
  f.centre_circle_diameter_mm = 1500;
  f.ball_diameter_mm = 100;
  f.border_mm = 700;
  set_field_constants(m, f);
  EXPECT_EQ(m.attr("FIELD_LENGTH").cast<int>(), 9000);
  EXPECT_EQ(m.attr("FIELD_WIDTH").cast<int>(), 6000);
  EXPECT_EQ(m.attr("GOAL_POST_ABS_X").cast<int>(), 4500);
  EXPECT_EQ(m.attr("GOAL_POST_ABS_Y").cast<int>(), 750);
  EXPECT_EQ(m.attr("GOAL_WIDTH").cast<int>(), 1500);
  EXPECT_EQ(m.attr("PENALTY_CROSS_ABS_X").cast<int>(), 3200);
  EXPECT_EQ(m.attr("PENALTY_AREA_LENGTH").cast<int>(), 1650);
  EXPECT_EQ(m.attr("GOAL_BOX_WIDTH").cast<int>(), 2200);
  EXPECT_EQ(m.attr("CENTER_CIRCLE_DIAMETER").cast<int>(), 1500);
  EXPECT_EQ(m.attr("BALL_RADIUS").cast<int>(), 50);
  EXPECT_EQ(m.attr("FULL_FIELD_LENGTH").cast<int>(), 10400);
  EXPECT_EQ(m.attr("CORNER_KICK_ABS_Y").cast<int>(), 3000);
  // The 2011 field has no separate penalty area: the goal box stands in for it.
  f.penalty_area_length_mm = 0;
  f.penalty_area_width_mm = 0;
  set_field_constants(m, f);
  EXPECT_EQ(m.attr("PENALTY_AREA_LENGTH").cast<int>(), 600);
  EXPECT_EQ(m.attr("PENALTY_AREA_WIDTH").cast<int>(), 2200);
}

TEST(RobotModule, JointLimitsAreTheNaos) {
  py::module_ m = py::module_::import(kModuleName);
  EXPECT_NEAR(m.attr("HeadYaw_Max").cast<double>(), 2.0857, 1e-6);
  EXPECT_NEAR(m.attr("HeadYaw_Min").cast<double>(), -2.0857, 1e-6);
  EXPECT_NEAR(m.attr("HeadPitch_Min").cast<double>(), -0.672, 1e-6);
  EXPECT_NEAR(m.attr("HeadPitch_Max").cast<double>(), 0.5149, 1e-6);
  EXPECT_TRUE(py::hasattr(m, "RHand_Max"));
}

TEST(RobotModule, SayWritesALineAndReturns) {
  testing::internal::CaptureStderr();
  run("robot.say('hello')");
  EXPECT_NE(testing::internal::GetCapturedStderr().find("says: hello"), std::string::npos);
}
