// The kick and the dribble end to end: a robot and the ball in an InProcessMatch, a
// behaviour that requests one kick, and the ball moving only because the swinging foot
// (a Box2D body) hits it. Distances are measured, not modelled.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "touchline/inprocess/inprocess_match.hpp"

using namespace touchline;
using api::ActionCommand::ActionType;
using api::ActionCommand::Foot;

namespace {

const float kFootHalfLength = sim::PhysicsDef{}.foot_length_mm / 2;
const float kBallRadius = sim::PhysicsDef{}.ball_diameter_mm / 2;
const float kFootOffset = robot::WalkDef{}.foot_separation_mm / 2;
// The robot stands well inside a 9 m x 6 m field facing along this heading, so even a
// long kick stops on the carpet before any line, post or wall.
const Pose2D kRobot{-3500.f, -500.f, 0.3f};

/// Requests one kick (or dribble), then, once it sees the recover phase, walks forward
/// (walk_after) or stands. Requesting the kick through the recover phase would start
/// another when it completes.
class KickOnce : public api::Behaviour {
 public:
  KickOnce(api::ActionCommand::Body kick, bool walk_after) : kick_(kick), walk_after_(walk_after) {}

  api::ActionCommand::All tick(const api::Blackboard& blackboard) override {
    if (blackboard.motion.kickPhase == 3) recovering_ = true;
    api::ActionCommand::All request;
    if (!recovering_) request.body = kick_;
    else if (walk_after_) request.body = api::ActionCommand::walk(200, 0, 0);
    return request;
  }

 private:
  api::ActionCommand::Body kick_;
  bool walk_after_;
  bool recovering_ = false;
};

struct Scene {
  ActionType type = ActionType::KICK;
  float power = 1.f;
  float bend = 0.f;
  Foot foot = Foot::LEFT;
  float gap_mm = 40.f;       ///< toe to ball surface, along the swing direction
  float side_mm = 0.f;       ///< ball centre off the swing line, + to the robot's left
  bool walk_after = false;
  float seconds = 12.f;      ///< simulated time to run (the ball must have stopped)
  std::string engine = "walkcycle"; ///< the robot's walk engine
};

struct Outcome {
  float forward_mm = 0;      ///< ball travel along the robot's heading
  float left_mm = 0;         ///< ball travel to the robot's left
  float launch_mm_s = 0;     ///< fastest the ball went
  float robot_forward_mm = 0;///< body travel along its initial heading by the end
  float feet_moved_mm = 0;   ///< the farther foot's distance from where it was placed
  api::MotionBlackboard motion; ///< at the end
  float distance() const { return std::hypot(forward_mm, left_mm); }
  float direction() const { return std::atan2(left_mm, forward_mm); }
};

/// `p` moved by (forward, left) in the frame of a pose heading `theta`.
Pose2D offset(const Pose2D& p, float theta, float forward, float left) {
  const float c = std::cos(theta), s = std::sin(theta);
  return {p.x_mm + c * forward - s * left, p.y_mm + s * forward + c * left, p.theta_rad};
}

Outcome play(const Scene& scene) {
  sim::WorldConfig config;
  config.field.length_mm = 9000;
  config.field.width_mm = 6000;
  config.match.team_size = 1;
  config.match.duration_s = scene.seconds;
  config.rules.referee = false; // physics only: no INITIAL/SET holding the robot still
  inprocess::InProcessMatch match(config);
  api::ActionCommand::Body kick;
  kick.actionType = scene.type;
  kick.power = scene.power;
  kick.bend = scene.bend;
  kick.foot = scene.foot;
  const RobotId id{0, 1};
  robot::RobotDef def;
  def.id = id;
  def.behaviour.name = "KickOnce";
  def.engine.name = scene.engine;
  match.add_robot(def, std::make_unique<KickOnce>(kick, scene.walk_after));
  match.start();

  sim::World& world = match.match().world();
  world.place_robot(0, kRobot);
  // The kicking foot's centre, then the ball ahead of its toe along the swing direction
  // (the foot turns to bend about its centre before striking).
  const float side = scene.foot == Foot::LEFT ? kFootOffset : -kFootOffset;
  const Pose2D foot = offset(kRobot, kRobot.theta_rad, 0, side);
  const float swing = kRobot.theta_rad + scene.bend;
  const Pose2D ball = offset(foot, swing, kFootHalfLength + scene.gap_mm + kBallRadius, scene.side_mm);
  world.place_ball(ball.x_mm, ball.y_mm);

  Outcome out;
  while (!match.match().finished()) {
    match.step_frame();
    const sim::BallTruth b = world.ball();
    out.launch_mm_s = std::max(out.launch_mm_s, std::hypot(b.vx_mm_s, b.vy_mm_s));
  }
  const sim::BallTruth end = world.ball();
  const float dx = end.x_mm - ball.x_mm, dy = end.y_mm - ball.y_mm;
  const float c = std::cos(kRobot.theta_rad), s = std::sin(kRobot.theta_rad);
  out.forward_mm = c * dx + s * dy;
  out.left_mm = -s * dx + c * dy;
  const sim::RobotTruth truth = world.robot(0);
  out.robot_forward_mm = c * (truth.body.x_mm - kRobot.x_mm) + s * (truth.body.y_mm - kRobot.y_mm);
  for (const auto& [now, was] : {std::pair{truth.left_foot, offset(kRobot, kRobot.theta_rad, 0, kFootOffset)},
                                 std::pair{truth.right_foot, offset(kRobot, kRobot.theta_rad, 0, -kFootOffset)}})
    out.feet_moved_mm = std::max(out.feet_moved_mm, std::hypot(now.x_mm - was.x_mm, now.y_mm - was.y_mm));
  out.motion = match.robot(id).blackboard().motion;
  EXPECT_LT(std::hypot(end.vx_mm_s, end.vy_mm_s), 1.f) << "the ball is still rolling";
  std::cout << api::ActionCommand::name(scene.type) << " power " << scene.power << " bend "
            << scene.bend << " gap " << scene.gap_mm << " side " << scene.side_mm
            << ": ball went " << out.distance() << " mm at " << out.direction()
            << " rad off the heading, launched at " << out.launch_mm_s << " mm/s" << std::endl;
  return out;
}

} // namespace

TEST(Kick, AlignedPowerOneKickSendsTheBallAtLeastThreeMetresAlongTheHeading) {
  for (float gap : {20.f, 40.f, 60.f}) {
    Scene scene;
    scene.gap_mm = gap;
    const Outcome out = play(scene);
    EXPECT_GE(out.distance(), 3000.f) << "gap " << gap;
    EXPECT_LE(out.distance(), 6000.f) << "gap " << gap;
    EXPECT_NEAR(out.direction(), 0.f, 0.05f) << "gap " << gap;
    EXPECT_LT(out.feet_moved_mm, 1.f) << "the swing returns the foot to where it started";
  }
}

TEST(Kick, RightFootKicksJustTheSame) {
  Scene scene;
  scene.foot = Foot::RIGHT;
  const Outcome out = play(scene);
  EXPECT_GE(out.distance(), 3000.f);
  EXPECT_NEAR(out.direction(), 0.f, 0.05f);
}

TEST(Kick, BallBesideTheKickingFootDoesNotMove) {
  Scene scene;
  scene.side_mm = 150.f; // outside the left foot: the swing passes it by
  const Outcome out = play(scene);
  EXPECT_LT(out.distance(), 1.f);
  EXPECT_EQ(out.launch_mm_s, 0.f);
}

TEST(Kick, BallOffTheToesCornerGlancesOffToThatSide) {
  // Foot placement decides the direction: the ball's centre 55 mm off the foot's centre
  // line (the foot is 90 mm wide) meets the toe's rounded corner.
  Scene outside;
  outside.side_mm = 55.f;
  const Outcome to_left = play(outside);
  EXPECT_GT(to_left.direction(), 0.1f);
  EXPECT_LT(to_left.direction(), 0.4f);
  EXPECT_LT(to_left.distance(), play(Scene{}).distance());

  Scene mirrored = outside;
  mirrored.foot = Foot::RIGHT;
  mirrored.side_mm = -55.f;
  EXPECT_NEAR(play(mirrored).direction(), -to_left.direction(), 0.01f);
}

TEST(Kick, BentKickSendsTheBallOffAxisToTheSideOfTheBend) {
  Scene left;
  left.bend = 0.3f;
  const Outcome to_left = play(left);
  EXPECT_GE(to_left.distance(), 2000.f);
  EXPECT_NEAR(to_left.direction(), 0.3f, 0.1f);

  Scene right;
  right.bend = -0.3f;
  right.foot = Foot::RIGHT;
  const Outcome to_right = play(right);
  EXPECT_NEAR(to_right.direction(), -0.3f, 0.1f);
}

TEST(Kick, DribbleMovesTheBallLessThanAKick) {
  Scene dribble;
  dribble.type = ActionType::DRIBBLE;
  const Outcome dribbled = play(dribble);
  EXPECT_GE(dribbled.distance(), 500.f);
  EXPECT_LE(dribbled.distance(), 1500.f);
  EXPECT_NEAR(dribbled.direction(), 0.f, 0.05f);
  EXPECT_LT(dribbled.distance(), play(Scene{}).distance() / 2);
}

TEST(Kick, LowerPowerKicksShorter) {
  Scene half;
  half.power = 0.5f;
  EXPECT_LT(play(half).distance(), play(Scene{}).distance());
}

TEST(Kick, RobotWalksAgainAfterTheKickCompletes) {
  Scene scene;
  scene.walk_after = true;
  scene.seconds = 8.f;
  const Outcome out = play(scene);
  EXPECT_EQ(out.motion.kickPhase, 0);
  EXPECT_EQ(out.motion.active.actionType, ActionType::WALK);
  EXPECT_FALSE(out.motion.standing);
  // The kick takes 1.7 s from standing; the rest is walking at up to 200 mm/s.
  EXPECT_GT(out.robot_forward_mm, 300.f);
}

TEST(Kick, TheJointWalksKickThroughTheLegsSendsTheBallAsFar) {
  // The nao-joints engine kicks with the same plan, through inverse and forward
  // kinematics: the foot the world swings hits the ball as the walkcycle engine's does.
  for (Foot foot : {Foot::LEFT, Foot::RIGHT}) {
    Scene scene;
    scene.foot = foot;
    const Outcome feet = play(scene);
    scene.engine = "nao-joints";
    const Outcome joints = play(scene);
    EXPECT_GE(joints.distance(), 3000.f);
    EXPECT_NEAR(joints.distance(), feet.distance(), 0.05f * feet.distance());
    EXPECT_NEAR(joints.direction(), 0.f, 0.05f);
  }
}

TEST(Kick, EveryWalkEngineOfThisBuildKicksTheBallForward) {
  // In a build with rUNSWift's walk (-DTOUCHLINE_RUNSWIFT_DIR) their own kick swings the
  // foot through our kinematics and hits the ball by contact, as ours does.
  for (const std::string& engine : robot::walk_engine_names()) {
    Scene scene;
    scene.engine = engine;
    const Outcome out = play(scene);
    EXPECT_GE(out.distance(), 1000.f) << engine;
    EXPECT_NEAR(out.direction(), 0.f, 0.3f) << engine;
  }
}
