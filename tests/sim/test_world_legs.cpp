// sim/src/world_legs.cpp, through World: the legs hold a robot's feet together (within
// reach, their headings within the hip's twist) whatever pushes them, and return a lifted
// foot to where the walk's own steps put it beside the standing one.
#include "touchline/sim/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"
#include "world_scenes.hpp"

namespace touchline::sim {
namespace {

using testing::kBlue1;
using testing::kRed1;
using testing::park_ball;

// --- the legs hold a robot together ------------------------------------------------------

/// Foot centres' distance of robot `index`.
float foot_spread(const World& world, int index) {
  const RobotTruth r = world.robot(index);
  return std::hypot(r.left_foot.x_mm - r.right_foot.x_mm, r.left_foot.y_mm - r.right_foot.y_mm);
}

// A robot walks at 0.5 m/s into a standing one from each of 16 directions, for 2 s, aimed at
// the standing robot's left foot, its right foot or its middle: however it is hit, the
// standing robot's feet never part further than the legs allow. Box2D keeps a stretched
// limit within its linear slop (5 mm).
TEST(World, APushFromAnySideMovesTheRobotNotOneFootAway) {
  const PhysicsDef physics;
  float worst = 0;
  float moved = 0;
  for (int side = 0; side < 16; ++side) {
    for (float aim_y_mm : {-50.f, 0.f, 50.f}) {
      World world(FieldDef{}, physics);
      world.add_robot(kRed1, Pose2D{0, 0, 0});
      park_ball(world);
      const float from = static_cast<float>(side) * kPi / 8;
      const Pose2D start{400 * std::cos(from), 400 * std::sin(from) + aim_y_mm, normalise_angle(from + kPi)};
      world.add_robot(kBlue1, start);
      TickMotion forward;
      forward.left.dx_mm = forward.right.dx_mm = 5;
      for (int t = 0; t < 200; ++t) {
        world.step({TickMotion{}, forward});
        worst = std::max(worst, foot_spread(world, 0));
      }
      const Pose2D body = world.robot(0).body;
      moved = std::max(moved, std::hypot(body.x_mm, body.y_mm));
    }
  }
  EXPECT_LE(worst, physics.max_foot_spread_mm + 5.5f) << "feet parted " << worst << " mm";
  EXPECT_GT(moved, 300.f) << "the pushed robot moved as a whole";
}

// The legs are slack below their length: a robot walking sideways, its feet 100 mm to
// 250 mm apart, moves exactly as commanded.
TEST(World, TheLegsDoNotHoldFeetWithinTheirReach) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  park_ball(world);
  TickMotion apart;
  apart.left.dy_mm = 1.5f; // 150 mm in 100 ticks
  for (int t = 0; t < 100; ++t) world.step({apart});
  EXPECT_NEAR(foot_spread(world, 0), 250.f, 0.5f);
}

// The legs stop a foot commanded beyond them: the other foot is dragged along.
TEST(World, AFootCommandedBeyondTheLegsDragsTheOther) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  park_ball(world);
  TickMotion apart;
  apart.left.dy_mm = 5;
  for (int t = 0; t < 100; ++t) world.step({apart}); // 500 mm, if nothing held it
  EXPECT_LE(foot_spread(world, 0), world.physics().max_foot_spread_mm + 5.5f);
  EXPECT_GT(world.robot(0).right_foot.y_mm, -50.f + 100.f) << "the right foot was dragged along";
}

/// How far apart the feet's headings are, rad (0 to pi).
float feet_twist(const RobotTruth& r) { return std::fabs(normalise_angle(r.right_foot.theta_rad - r.left_foot.theta_rad)); }

/// What robot 0's feet did in a run: the largest jump of its body heading between two ticks,
/// and the largest twist (one foot's heading less the other's) at any tick.
struct TwistRun {
  float jump = 0;
  float twist = 0;
};

/// Robot 0 at the origin moves its feet by `own` every tick, while robot 1's feet (from
/// `other`, none: no robot 1) move by `push`; 100 ticks.
TwistRun run_feet(const PhysicsDef& physics, const TickMotion& own, const Pose2D* other = nullptr,
                  const TickMotion& push = {}) {
  World world(FieldDef{}, physics);
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  if (other) world.add_robot(kBlue1, *other);
  park_ball(world);
  TwistRun run;
  float heading = world.robot(0).body.theta_rad;
  for (int t = 0; t < 100; ++t) {
    if (other) world.step({own, push});
    else world.step({own});
    const RobotTruth r = world.robot(0);
    run.jump = std::max(run.jump, std::fabs(normalise_angle(r.body.theta_rad - heading)));
    run.twist = std::max(run.twist, feet_twist(r));
    heading = r.body.theta_rad;
  }
  return run;
}

/// Robot 1 walks into robot 0 from its front left, turning as it comes, and shoves it along:
/// its feet spin robot 0's left foot (the contacts of a match's pushes).
TwistRun shoved(const PhysicsDef& physics) {
  const Pose2D other{150, 300, -0.5f * kPi};
  TickMotion drive;
  drive.left.dx_mm = drive.right.dx_mm = 20;
  drive.left.dtheta_rad = drive.right.dtheta_rad = -0.1f;
  return run_feet(physics, TickMotion{}, &other, drive);
}

// The legs hold the feet's headings within max_foot_twist_rad against a contact, so the body's
// heading (their mean) cannot flip. Without the limit the contact turns them further apart.
TEST(World, TheLegsHoldTheFeetsHeadingsTogetherAgainstAContact) {
  PhysicsDef physics;
  ASSERT_GT(physics.max_foot_twist_rad, 0.f) << "the limit is on by default";
  const TwistRun held = shoved(physics);
  EXPECT_LE(held.twist, physics.max_foot_twist_rad + 1e-3f);
  EXPECT_LT(held.jump, 0.2f) << "the body heading jumped";
  PhysicsDef free = physics;
  free.max_foot_twist_rad = 0;
  // Robot 1's legs also put its lifted feet back in its stance, which changes its shove; the
  // shove that flips robot 0 is the one with robot 1's feet left where the contact turns them.
  free.stance_return_mm_s = free.stance_return_rad_s = 0;
  EXPECT_GT(shoved(free).jump, 3.f) << "without the limit, the body flips about (the case the limit is for)";
}

// The walk's own turn is never held within the legs' reach: a foot turned by its command, 1 rad
// over 100 ticks, turns exactly as far with the limit as without it (a turning walk opens the
// feet ~0.83 rad).
TEST(World, TheLegsLeaveTheWalksOwnTwistAlone) {
  PhysicsDef physics;
  TickMotion turn;
  turn.left.dtheta_rad = 0.01f;
  PhysicsDef free = physics;
  free.max_foot_twist_rad = 0;
  World held(FieldDef{}, physics), loose(FieldDef{}, free);
  for (World* w : {&held, &loose}) {
    w->add_robot(kRed1, Pose2D{0, 0, 0});
    park_ball(*w);
  }
  for (int t = 0; t < 100; ++t) {
    held.step({turn});
    loose.step({turn});
    ASSERT_EQ(held.robot(0).left_foot.theta_rad, loose.robot(0).left_foot.theta_rad) << "tick " << t;
    ASSERT_EQ(held.robot(0).right_foot.theta_rad, loose.robot(0).right_foot.theta_rad) << "tick " << t;
  }
}

// A contact's twist is held even while the walk turns the feet the same way: robot 0 opens
// its feet to 0.6 rad and closes them again, over and over, while robot 1 shoves it. The
// feet stay within max_foot_twist_rad of each other at every tick (the bound once took the
// walk's turn on top of whatever twist the feet had, and ratcheted up to the feet pi apart).
TEST(World, TheLegsHoldAContactsTwistWhileTheWalkTurns) {
  PhysicsDef physics;
  World world(FieldDef{}, physics);
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  world.add_robot(kBlue1, Pose2D{150, 300, -0.5f * kPi});
  park_ball(world);
  TickMotion drive;
  drive.left.dx_mm = drive.right.dx_mm = 20;
  drive.left.dtheta_rad = drive.right.dtheta_rad = -0.1f;
  float worst = 0;
  for (int t = 0; t < 300; ++t) {
    TickMotion turn;
    turn.right.dtheta_rad = (t / 30) % 2 == 0 ? 0.02f : -0.02f; // 0 -> 0.6 rad -> 0, every 60 ticks
    world.step({turn, drive});
    const RobotTruth r = world.robot(0);
    worst = std::max(worst, feet_twist(r));
  }
  EXPECT_LE(worst, physics.max_foot_twist_rad + 1e-3f);
}

// Even the walk cannot turn the feet further apart than a Nao's hip joint can (1.15 rad): a
// walk that asks for 5 rad over 100 ticks has the feet held at the joint's limit.
TEST(World, TheWalksOwnTwistStopsAtTheLegsLimit) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  park_ball(world);
  TickMotion turn;
  turn.left.dtheta_rad = 0.05f;
  float worst = 0;
  for (int t = 0; t < 100; ++t) {
    world.step({turn});
    const RobotTruth r = world.robot(0);
    worst = std::max(worst, feet_twist(r));
  }
  EXPECT_NEAR(worst, 1.15f, 1e-3f);
}

// --- the legs hold the walk's stance -------------------------------------------------------

/// Adds robot 0 at the origin, whose walk moves its legs by `step` for 50 ticks while the
/// world moves neither foot (a step the referee stopped: step's `legs`), so its feet are
/// square but its walk's stance is not. By default the left foot steps 100 mm forward.
void stop_a_step(World& world, const TickMotion& step = {FootMotion{2, 0, 0}, FootMotion{}}) {
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  park_ball(world);
  for (int t = 0; t < 50; ++t) world.step({TickMotion{}}, {step});
}

/// Robot 0 lifts its left foot for 60 ticks, the walk moving it 0.05 mm a tick (3 mm in all).
void lift_left_foot(World& world) {
  TickMotion lift;
  lift.left.dx_mm = 0.05f;
  for (int t = 0; t < 60; ++t) world.step({lift});
}

// A step the referee stopped leaves the feet where they were; the next time the walk lifts
// that foot, the legs put it where the walk's own steps put it: 100 mm ahead of the other
// (and the 3 mm the walk now moves it), at up to stance_return_mm_s. The standing foot never
// moves. Without the return the foot moves only its 3 mm, and the robot's stance stays
// 100 mm off its walk's for the rest of the match.
TEST(World, TheLegsPutALiftedFootBackInTheWalksStance) {
  PhysicsDef physics;
  ASSERT_GT(physics.stance_return_mm_s, 0.f) << "on by default";
  World world(FieldDef{}, physics);
  stop_a_step(world);
  const RobotTruth before = world.robot(0);
  EXPECT_NEAR(before.left_foot.x_mm, 0, 1e-3f) << "a stopped step moves no foot";
  lift_left_foot(world);
  const RobotTruth after = world.robot(0);
  EXPECT_NEAR(after.left_foot.x_mm, 103, 0.05f);
  EXPECT_NEAR(after.left_foot.y_mm, before.left_foot.y_mm, 0.05f);
  EXPECT_NEAR(after.right_foot.x_mm, before.right_foot.x_mm, 1e-3f) << "the standing foot stays";
  EXPECT_NEAR(after.right_foot.y_mm, before.right_foot.y_mm, 1e-3f);
  EXPECT_NEAR(feet_twist(after), 0, 1e-5f);

  PhysicsDef off = physics;
  off.stance_return_mm_s = off.stance_return_rad_s = 0;
  World loose(FieldDef{}, off);
  stop_a_step(loose);
  lift_left_foot(loose);
  EXPECT_NEAR(loose.robot(0).left_foot.x_mm, 3, 0.05f) << "without the return, only the walk's 3 mm";
}

// A robot put down stands square: the stance its walk had before is forgotten (its walk
// stands square too, RobotSense::placed), so a lifted foot moves only as the walk moves it.
TEST(World, APlacedRobotsStanceIsSquare) {
  World world(FieldDef{}, PhysicsDef{});
  stop_a_step(world);
  world.place_robot(0, Pose2D{500, 0, 0});
  lift_left_foot(world);
  EXPECT_NEAR(world.robot(0).left_foot.x_mm, 503, 0.05f);
}

// The return turns a lifted foot back too: the walk turned its right foot 0.5 rad in a step
// the referee stopped; lifted, it turns to 0.5 rad from the left foot at up to
// stance_return_rad_s (2 rad/s: 0.25 s), and no further.
TEST(World, TheLegsTurnALiftedFootBackToTheWalksTwist) {
  World world(FieldDef{}, PhysicsDef{});
  TickMotion turn;
  turn.right.dtheta_rad = 0.01f;
  stop_a_step(world, turn);
  TickMotion lift;
  lift.right.dx_mm = 0.05f;
  for (int t = 0; t < 20; ++t) world.step({lift});
  const float halfway = feet_twist(world.robot(0));
  EXPECT_GT(halfway, 0.3f);
  EXPECT_LT(halfway, 0.45f) << "at most 0.02 rad a tick";
  for (int t = 0; t < 40; ++t) world.step({lift});
  EXPECT_NEAR(feet_twist(world.robot(0)), 0.5f, 1e-4f);
}

TEST(World, RejectsLegMotionsThatDoNotMatchTheRobots) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{});
  EXPECT_THROW(world.step({TickMotion{}}, {}), std::invalid_argument);
}

} // namespace
} // namespace touchline::sim
