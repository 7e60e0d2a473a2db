#include "touchline/robot/robot.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace touchline;
using namespace touchline::api;

namespace {

/// Records what it saw and asks for a fixed walk.
class Probe : public Behaviour {
 public:
  ActionCommand::All tick(const Blackboard& blackboard) override {
    seen_utime = blackboard.utime;
    seen_pos = blackboard.localisation.robotPos;
    seen_ball = blackboard.localisation.ballPosRR;
    seen_player = blackboard.gameController.playerNumber;
    ++ticks;
    ActionCommand::All all;
    all.body = body;
    all.leds.chest = 0xff0000;
    return all;
  }
  ActionCommand::Body body = ActionCommand::walk(100, 0, 0); ///< what it asks for
  int64_t seen_utime = -1;
  AbsCoord seen_pos;
  RRCoord seen_ball;
  int seen_player = 0;
  int ticks = 0;
};

/// A robot running a Probe.
robot::RobotDef robot_def(RobotId id) {
  robot::RobotDef def;
  def.id = id;
  def.behaviour.name = "probe";
  return def;
}

SenseFrame frame_with(RobotSense sense, int64_t frame_index) {
  SenseFrame frame;
  frame.frame = frame_index;
  frame.utime = frame_start_utime(frame_index);
  frame.motion_ticks = ticks_in_frame(frame_index);
  frame.robots.push_back(sense);
  return frame;
}

} // namespace

TEST(Robot, OneFrameRunsTheBehaviourOnceAndTheFramesMotionTicks) {
  auto probe_owner = std::make_unique<Probe>();
  Probe& probe = *probe_owner;
  robot::Robot robot(robot_def({0, 3}), std::move(probe_owner));
  RobotSense sense;
  sense.id = {0, 3};
  sense.truth = {1000, 0, kPi / 2};
  sense.ball_x_mm = 1000;
  sense.ball_y_mm = 500; // straight ahead of a robot facing +y
  sense.seen.push_back({ObjectKind::kBall, 0, 500, 0, 0.5f});
  const SenseFrame frame = frame_with(sense, 2);
  const RobotAct act = robot.step(frame, frame.robots[0]);

  EXPECT_EQ(probe.ticks, 1);
  EXPECT_EQ(probe.seen_utime, frame_start_utime(2));
  EXPECT_EQ(probe.seen_player, 3);
  EXPECT_FLOAT_EQ(probe.seen_pos.x, 1000);
  EXPECT_NEAR(probe.seen_ball.distance, 500, 1e-3);
  EXPECT_NEAR(probe.seen_ball.heading, 0, 1e-6);

  EXPECT_EQ(act.id, (RobotId{0, 3}));
  EXPECT_EQ(act.frame, 2);
  EXPECT_EQ(act.motion_ticks, 4); // frame 2 holds ticks 6..9
  EXPECT_EQ(act.leds, 0xff0000);
  EXPECT_EQ(robot.blackboard().motion.ticks, 4);
  EXPECT_EQ(robot.blackboard().motion.active.actionType, ActionCommand::ActionType::WALK);
}

TEST(Robot, WalkingRobotReportsFootMotionAndOdometry) {
  robot::Robot robot(robot_def({1, 1}), std::make_unique<Probe>());
  RobotSense sense;
  sense.id = {1, 1};
  float moved = 0;
  for (int64_t f = 0; f < 90; ++f) { // 3 s
    const SenseFrame frame = frame_with(sense, f);
    const RobotAct act = robot.step(frame, frame.robots[0]);
    for (int i = 0; i < act.motion_ticks; ++i) moved += (act.ticks[i].left.dx_mm + act.ticks[i].right.dx_mm) / 2;
  }
  EXPECT_GT(robot.blackboard().motion.odometry.x, 200.f);
  EXPECT_NEAR(moved, robot.blackboard().motion.odometry.x, 0.05f * robot.blackboard().motion.odometry.x);
  EXPECT_GE(robot.behaviour_cpu_us(), 0);
}

/// How far robot's feet move in the frame `sense` makes (both feet, every tick), mm.
float feet_travel(robot::Robot& robot, const RobotSense& sense, int64_t frame_index) {
  const SenseFrame frame = frame_with(sense, frame_index);
  const RobotAct act = robot.step(frame, frame.robots[0]);
  float travel = 0;
  for (int i = 0; i < act.motion_ticks; ++i)
    for (const FootMotion& m : {act.ticks[i].left, act.ticks[i].right}) travel += std::hypot(m.dx_mm, m.dy_mm);
  return travel;
}

// The referee put the robot down (feet square, RobotSense::placed) mid-step: it stands square
// at once, so its next steps start from the feet the world placed. Unplaced, the walk asked
// to stand first finishes the step it is in.
TEST(Robot, ARobotPutDownStandsSquareInItsWalk) {
  for (const bool placed : {true, false}) {
    auto probe_owner = std::make_unique<Probe>();
    Probe& probe = *probe_owner;
    robot::Robot robot(robot_def({0, 2}), std::move(probe_owner));
    RobotSense sense;
    sense.id = {0, 2};
    for (int64_t f = 0; f < 20; ++f) feet_travel(robot, sense, f);
    ASSERT_FALSE(robot.motion().walk().standing()) << "walking";
    probe.body = ActionCommand::stand();
    sense.placed = placed;
    const float travel = feet_travel(robot, sense, 20);
    if (placed) {
      EXPECT_EQ(travel, 0.f) << "standing square: no foot moves";
      EXPECT_TRUE(robot.motion().walk().standing());
    } else {
      EXPECT_GT(travel, 1.f) << "the walk finishes its step";
    }
  }
}

TEST(Robot, TeamOneSeesTheFieldFromItsOwnSide) {
  // +x towards the opponent goal for both teams: the world's frame is team 0's.
  auto probe_owner = std::make_unique<Probe>();
  Probe& probe = *probe_owner;
  robot::RobotDef def = robot_def({1, 2});
  def.localisation.perfect = true;
  robot::Robot robot(def, std::move(probe_owner));
  RobotSense sense;
  sense.id = {1, 2};
  sense.truth = {1000, 300, kPi}; // on team 1's own half, facing the goal it attacks
  const SenseFrame frame = frame_with(sense, 0);
  const RobotAct act = robot.step(frame, frame.robots[0]);
  EXPECT_FLOAT_EQ(probe.seen_pos.x, -1000);
  EXPECT_FLOAT_EQ(probe.seen_pos.y, -300);
  EXPECT_NEAR(probe.seen_pos.theta, 0, 1e-6);
  EXPECT_FLOAT_EQ(act.localised.x_mm, 1000); // the belief goes back to the world in its frame
  EXPECT_NEAR(std::fabs(act.localised.theta_rad), kPi, 1e-6);
}

TEST(Robot, TheBeliefGoesToTheWorldInItsFrameWithTheCovariance) {
  // The viewer draws act_t's belief: the pose's position covariance and the ball, field frame.
  robot::Robot robot(robot_def({1, 2}), std::make_unique<Probe>()); // its own filters, not the truth
  RobotSense sense;
  sense.id = {1, 2};
  sense.truth = {1000, 300, kPi};
  const SenseFrame frame = frame_with(sense, 0);
  const RobotAct act = robot.step(frame, frame.robots[0]);
  const api::LocalisationBlackboard& loc = robot.blackboard().localisation; // team 1's frame
  EXPECT_GT(act.localised_cov_mm2[0], 0.f) << "a filter's pose has an uncertainty";
  EXPECT_FLOAT_EQ(act.localised_cov_mm2[0], loc.robotPosCovariance[0]);
  EXPECT_FLOAT_EQ(act.localised_cov_mm2[1], loc.robotPosCovariance[1]); // a half turn keeps xy
  EXPECT_FLOAT_EQ(act.localised_cov_mm2[2], loc.robotPosCovariance[4]);
  EXPECT_FLOAT_EQ(act.ball_x_mm, -loc.ballPos.x);
  EXPECT_FLOAT_EQ(act.ball_y_mm, -loc.ballPos.y);
  EXPECT_EQ(act.ball_lost_frames, loc.ballLostCount);
}

TEST(Robot, ReceiverKeepsTheLatestMessageOfEachTeammate) {
  robot::Robot robot(robot_def({0, 1}), std::make_unique<Probe>());
  RobotSense sense;
  sense.id = {0, 1};
  sense.messages = {{3, 100, {7}}, {2, 50, {5}}, {3, 200, {8}}};
  robot.step(frame_with(sense, 0), sense);
  sense.messages = {{2, 40, {4}}}; // older than what we have from player 2: ignored
  robot.step(frame_with(sense, 1), sense);
  const auto& messages = robot.blackboard().receiver.messages;
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0].playerNumber, 2);
  EXPECT_EQ(messages[0].data, std::vector<uint8_t>{5});
  EXPECT_EQ(messages[1].playerNumber, 3);
  EXPECT_EQ(messages[1].data, std::vector<uint8_t>{8});
}

TEST(Robot, EverythingComesFromItsDef) {
  robot::RobotDef def = robot_def({1, 4});
  def.behaviour = {"goto", {{"y", "-5"}, {"x", "12"}}, {}};
  def.walk.max_forward_mm_s = 123;
  def.kick.kick.peak_speed_mm_s = 2345;
  def.kick.dribble.recover_s = 0.75f;
  def.head.max_yaw_rad = 1.25f;
  robot::Robot robot(def, std::make_unique<Probe>());
  EXPECT_EQ(robot.id(), (RobotId{1, 4}));
  EXPECT_EQ(robot.blackboard().behaviour.skill, "goto x=12 y=-5"); // what snapshots record as running
  EXPECT_FLOAT_EQ(robot.motion().walk().def().max_forward_mm_s, 123);
  EXPECT_FLOAT_EQ(robot.motion().kick().def().kick.peak_speed_mm_s, 2345);
  EXPECT_FLOAT_EQ(robot.motion().kick().def().dribble.recover_s, 0.75f);
  EXPECT_FLOAT_EQ(robot.def().head.max_yaw_rad, 1.25f);
}

TEST(Robot, NeedsABehaviour) {
  EXPECT_THROW(robot::Robot(robot_def({0, 1}), nullptr), std::invalid_argument);
}
