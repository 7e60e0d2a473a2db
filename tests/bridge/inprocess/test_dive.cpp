// The goalie dive end to end: a robot and a rolling ball in an InProcessMatch, a behaviour
// that asks for one dive, and the ball stopped only because the robot's feet (Box2D bodies
// the world moves as the robot's acts say) lie in its path. Distances are measured.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include <gtest/gtest.h>

#include "touchline/inprocess/inprocess_match.hpp"

using namespace touchline;
using api::ActionCommand::ActionType;

namespace {

// The robot stands well inside a 9 m x 6 m field facing +x; the ball rolls at it along -x,
// 450 mm to its left: clear of its standing feet (outer edges 95 mm from its centre) by
// some 320 mm, inside a body length (the dive's reach).
const Pose2D kRobot{-3000.f, 0.f, 0.f};
constexpr float kBallLeftMm = 450.f;
constexpr float kBallStartAheadMm = 1000.f;
constexpr float kBallSpeedMmS = 1500.f;

/// Asks for `action` until motion shows it running, then stands (asking on would start
/// another dive once this one is over).
class ActOnce : public api::Behaviour {
 public:
  explicit ActOnce(ActionType action) : action_(action) {}
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override {
    if (blackboard.motion.active.actionType == action_) started_ = true;
    api::ActionCommand::All request;
    if (!started_) request.body.actionType = action_;
    return request;
  }

 private:
  ActionType action_;
  bool started_ = false;
};

struct Outcome {
  float ball_min_forward_mm = 0; ///< how far along the robot's heading the ball got (- behind it)
  float robot_left_mm = 0;       ///< body travel to the robot's left by the end
  bool motion_down_mid = false;  ///< at 1.5 s: the dive active, not standing
  api::MotionBlackboard motion;  ///< at the end
};

Outcome play(ActionType action, float seconds) {
  sim::WorldConfig config;
  config.field.length_mm = 9000;
  config.field.width_mm = 6000;
  config.match.team_size = 1;
  config.match.duration_s = seconds;
  config.rules.referee = false; // physics only
  inprocess::InProcessMatch match(config);
  const RobotId id{0, 1};
  robot::RobotDef def;
  def.id = id;
  def.behaviour.name = "ActOnce";
  match.add_robot(def, std::make_unique<ActOnce>(action));
  match.start();

  sim::World& world = match.match().world();
  world.place_robot(0, kRobot);
  world.place_ball(kRobot.x_mm + kBallStartAheadMm, kRobot.y_mm + kBallLeftMm, -kBallSpeedMmS, 0);

  Outcome out;
  bool checked_mid = false;
  out.ball_min_forward_mm = kBallStartAheadMm;
  while (!match.match().finished()) {
    match.step_frame();
    out.ball_min_forward_mm = std::min(out.ball_min_forward_mm, world.ball().x_mm - kRobot.x_mm);
    const auto& motion = match.robot(id).blackboard().motion;
    if (!checked_mid && motion.ticks >= 150) { // 1.5 s: down, not yet up (2.4 s)
      checked_mid = true;
      out.motion_down_mid = motion.active.actionType == action && !motion.standing;
    }
  }
  out.robot_left_mm = world.robot(0).body.y_mm - kRobot.y_mm;
  out.motion = match.robot(id).blackboard().motion;
  std::cout << api::ActionCommand::name(action) << ": the ball got to " << out.ball_min_forward_mm
            << " mm along the robot's heading; the robot moved " << out.robot_left_mm << " mm left" << std::endl;
  return out;
}

} // namespace

TEST(Dive, ADivingRobotsFeetBlockABallThatWouldPassBesideIt) {
  const float seconds = 3.f;
  const Outcome standing = play(ActionType::STAND, seconds);
  EXPECT_LT(standing.ball_min_forward_mm, -500.f) << "standing, the ball rolls past the robot";
  EXPECT_NEAR(standing.robot_left_mm, 0.f, 1.f);

  const Outcome away = play(ActionType::GOALIE_DIVE_RIGHT, seconds);
  EXPECT_LT(away.ball_min_forward_mm, -500.f) << "diving the other way, it rolls past too";
  EXPECT_NEAR(away.robot_left_mm, -robot::DiveDef{}.reach_mm, 5.f);

  const Outcome save = play(ActionType::GOALIE_DIVE_LEFT, seconds);
  EXPECT_GT(save.ball_min_forward_mm, 0.f) << "the feet stop it in front of the robot";
  EXPECT_NEAR(save.robot_left_mm, robot::DiveDef{}.reach_mm, 5.f) << "the world moved the feet as the dive asked";
  EXPECT_TRUE(save.motion_down_mid);
}

TEST(Dive, TheRobotStandsUpWhereItLandedAfterTheDivesDuration) {
  const Outcome out = play(ActionType::GOALIE_DIVE_LEFT, 3.f);
  EXPECT_TRUE(out.motion.standing);
  EXPECT_EQ(out.motion.active.actionType, ActionType::STAND);
  EXPECT_NEAR(out.motion.odometry.y, robot::DiveDef{}.reach_mm, 1.f);
}
