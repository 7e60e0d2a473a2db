// The physical world: feet move as commanded, the ball rolls, bounces and stops as the
// model says, contacts are physical, and the same inputs give the same world. The legs
// (holding a robot together and in its walk's stance): test_world_legs.cpp.
#include "touchline/sim/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "touchline/angles.hpp"
#include "world_scenes.hpp"

namespace touchline::sim {
namespace {

using testing::kBlue1;
using testing::kRed1;
using testing::park_ball;
using testing::run;
using testing::still;

float speed(const BallTruth& b) { return std::hypot(b.vx_mm_s, b.vy_mm_s); }


/// Depth by which two foot rectangles (length along their heading) overlap, 0 if apart
/// (separating axis theorem over the four edge normals).
float overlap_depth(const Pose2D& a, const Pose2D& b, float length, float width) {
  const auto corners = [&](const Pose2D& p) {
    std::array<std::array<float, 2>, 4> c{};
    const float cs = std::cos(p.theta_rad), sn = std::sin(p.theta_rad);
    const float hx[] = {length / 2, length / 2, -length / 2, -length / 2};
    const float hy[] = {width / 2, -width / 2, -width / 2, width / 2};
    for (int i = 0; i < 4; ++i)
      c[static_cast<std::size_t>(i)] = {p.x_mm + cs * hx[i] - sn * hy[i], p.y_mm + sn * hx[i] + cs * hy[i]};
    return c;
  };
  const auto ca = corners(a), cb = corners(b);
  float depth = 1e9f;
  for (float theta : {a.theta_rad, a.theta_rad + kPi / 2, b.theta_rad, b.theta_rad + kPi / 2}) {
    const float ax = std::cos(theta), ay = std::sin(theta);
    float amin = 1e9f, amax = -1e9f, bmin = 1e9f, bmax = -1e9f;
    for (const auto& p : ca) amin = std::min(amin, p[0] * ax + p[1] * ay), amax = std::max(amax, p[0] * ax + p[1] * ay);
    for (const auto& p : cb) bmin = std::min(bmin, p[0] * ax + p[1] * ay), bmax = std::max(bmax, p[0] * ax + p[1] * ay);
    depth = std::min(depth, std::min(amax, bmax) - std::max(amin, bmin));
  }
  return std::max(0.f, depth);
}

FieldDef long_field() {
  FieldDef def;
  def.length_mm = 9000;
  def.width_mm = 6000;
  return def;
}

// --- feet follow their commands -------------------------------------------------------

class FootDisplacement : public ::testing::TestWithParam<float> {};

TEST_P(FootDisplacement, MatchesTheCommandInTheBodyFrame) {
  const float heading = GetParam();
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-500, -300, heading});
  park_ball(world);
  const RobotTruth start = world.robot(0);
  TickMotion motion;
  motion.left.dx_mm = 10;  // 1 m/s forward
  motion.right.dy_mm = 4;  // 0.4 m/s to the robot's left
  for (int t = 0; t < 20; ++t) world.step({motion}); // 200 mm and 80 mm: within the legs' reach
  const RobotTruth end = world.robot(0);

  const float c = std::cos(heading), s = std::sin(heading);
  // Float precision, far inside the +-0.5 mm a walk needs (measured: < 0.01 mm).
  constexpr float kTol = 0.02f;
  EXPECT_NEAR(end.left_foot.x_mm, start.left_foot.x_mm + 200 * c, kTol);
  EXPECT_NEAR(end.left_foot.y_mm, start.left_foot.y_mm + 200 * s, kTol);
  EXPECT_NEAR(end.right_foot.x_mm, start.right_foot.x_mm - 80 * s, kTol);
  EXPECT_NEAR(end.right_foot.y_mm, start.right_foot.y_mm + 80 * c, kTol);
  EXPECT_NEAR(normalise_angle(end.body.theta_rad - heading), 0, 1e-5f);
  EXPECT_EQ(world.ticks(), 20);
}

INSTANTIATE_TEST_SUITE_P(Headings, FootDisplacement,
                         ::testing::Values(0.f, 0.7f, kPi / 2, -2.5f, 3.1f));

TEST(World, RobotStartsWithFeetSeparatedAlongItsY) {
  World world(FieldDef{}, PhysicsDef{}, 120.f);
  world.add_robot(kRed1, Pose2D{100, 200, kPi / 2});
  park_ball(world);
  const RobotTruth r = world.robot(0);
  EXPECT_EQ(r.id, kRed1);
  EXPECT_NEAR(r.left_foot.x_mm, 100 - 60, 1e-3f); // robot's left is field -x when facing +y
  EXPECT_NEAR(r.left_foot.y_mm, 200, 1e-3f);
  EXPECT_NEAR(r.right_foot.x_mm, 100 + 60, 1e-3f);
  EXPECT_NEAR(r.body.x_mm, 100, 1e-3f);
  EXPECT_NEAR(r.body.y_mm, 200, 1e-3f);
  EXPECT_NEAR(r.body.theta_rad, kPi / 2, 1e-6f);
  EXPECT_NEAR(r.left_foot.theta_rad, kPi / 2, 1e-6f);
}

TEST(World, TurningOnTheSpotAccumulatesTheCommandedHeading) {
  const float sep = 100, turn = 0.02f; // 2 rad/s
  World world(FieldDef{}, PhysicsDef{}, sep);
  world.add_robot(kRed1, Pose2D{300, 200, 1.f});
  park_ball(world);
  // Each foot moves along the chord of its circle about the body centre, and turns.
  TickMotion motion;
  motion.left = FootMotion{-sep / 2 * std::sin(turn), sep / 2 * (std::cos(turn) - 1), turn};
  motion.right = FootMotion{sep / 2 * std::sin(turn), -sep / 2 * (std::cos(turn) - 1), turn};
  for (int t = 0; t < 150; ++t) world.step({motion});
  const RobotTruth r = world.robot(0);
  const float expected = normalise_angle(1.f + 150 * turn); // 4 rad
  EXPECT_NEAR(normalise_angle(r.body.theta_rad - expected), 0, 1e-4f);
  EXPECT_NEAR(normalise_angle(r.left_foot.theta_rad - expected), 0, 1e-4f);
  EXPECT_NEAR(r.body.x_mm, 300, 0.05f);
  EXPECT_NEAR(r.body.y_mm, 200, 0.05f);
  // The left foot is still at +sep/2 along the body's y.
  EXPECT_NEAR(r.left_foot.x_mm, 300 - sep / 2 * std::sin(expected), 0.05f);
  EXPECT_NEAR(r.left_foot.y_mm, 200 + sep / 2 * std::cos(expected), 0.05f);
}

TEST(World, FeetOfOneRobotPassThroughEachOther) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  park_ball(world);
  const RobotTruth start = world.robot(0);
  TickMotion motion;
  motion.left.dy_mm = -10; // onto the right foot, centres 20 mm apart: the soles overlap by 70 mm
  for (int t = 0; t < 8; ++t) world.step({motion});
  const RobotTruth end = world.robot(0);
  EXPECT_NEAR(end.left_foot.y_mm, start.left_foot.y_mm - 80, 0.02f);
  EXPECT_NEAR(end.left_foot.x_mm, start.left_foot.x_mm, 0.02f);
  EXPECT_NEAR(end.right_foot.x_mm, start.right_foot.x_mm, 1e-3f);
  EXPECT_NEAR(end.right_foot.y_mm, start.right_foot.y_mm, 1e-3f);
}

TEST(World, PlaceRobotPutsTheFeetDownAtRest) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  park_ball(world);
  world.place_robot(0, Pose2D{-1000, 500, -kPi / 2});
  run(world, 10);
  const RobotTruth r = world.robot(0);
  EXPECT_NEAR(r.body.x_mm, -1000, 1e-3f);
  EXPECT_NEAR(r.body.y_mm, 500, 1e-3f);
  EXPECT_NEAR(r.body.theta_rad, -kPi / 2, 1e-6f);
  EXPECT_NEAR(r.left_foot.x_mm, -1000 + 50, 1e-3f);
}

TEST(World, RejectsAMotionCountThatDoesNotMatchTheRobots) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{});
  EXPECT_THROW(world.step({}), std::invalid_argument);
  EXPECT_THROW(world.robot(1), std::out_of_range);
  EXPECT_EQ(world.ticks(), 0);
}

// --- the ball ---------------------------------------------------------------------------

/// Distance to stop from v0 under dv/dt = -a - c v: v0/c - a/c^2 ln(1 + c v0 / a).
double stopping_distance(double v0, double a, double c) {
  if (c == 0) return v0 * v0 / (2 * a);
  return v0 / c - a / (c * c) * std::log(1 + c * v0 / a);
}

class BallRolling : public ::testing::TestWithParam<float> {};

TEST_P(BallRolling, StopsWhereTheDecelerationModelSays) {
  PhysicsDef physics;
  physics.ball_linear_damping = GetParam();
  World world(long_field(), physics);
  world.place_ball(-4000, 0, 2000, 0); // 2 m/s along the field
  int ticks = 0;
  while (speed(world.ball()) > 0 && ticks < 3000) {
    run(world, 1);
    ++ticks;
  }
  const BallTruth stopped = world.ball();
  const double expected = stopping_distance(2000, physics.ball_rolling_decel_mm_s2, GetParam());
  // Semi-implicit Euler at 5 ms steps is within a few mm of the continuous model.
  EXPECT_NEAR(stopped.x_mm + 4000, expected, 0.002 * expected);
  EXPECT_FLOAT_EQ(stopped.y_mm, 0);
  // It stays stopped: the resistance never reverses it.
  run(world, 100);
  EXPECT_FLOAT_EQ(world.ball().x_mm, stopped.x_mm);
  EXPECT_EQ(speed(world.ball()), 0.f);
}

// Damping 0: v^2 / 2a = 6667 mm; the default 0.2/s: 3645 mm.
INSTANTIATE_TEST_SUITE_P(Damping, BallRolling, ::testing::Values(0.f, 0.2f));

TEST(World, BallBouncesOffAPostWithThePostsRestitution) {
  PhysicsDef physics;
  physics.post_restitution = 0.2f;
  physics.ball_restitution = 0.9f; // Box2D alone would bounce with the max, 0.9
  World world(FieldDef{}, physics);
  const Pose2D post = world.field().goal_post(0, true);
  world.place_ball(post.x_mm + 500, post.y_mm, -2000, 0);
  float before = 0, after = 0;
  for (int t = 0; t < 100 && after <= 0; ++t) {
    before = world.ball().vx_mm_s;
    run(world, 1);
    after = world.ball().vx_mm_s;
  }
  ASSERT_GT(after, 0) << "the ball did not bounce back";
  EXPECT_NEAR(after / -before, 0.2f, 0.03f);
  run(world, 100);
  EXPECT_GT(world.ball().x_mm, post.x_mm); // back in the field, not in the goal
}

class ShotIntoNet : public ::testing::TestWithParam<float> {};

TEST_P(ShotIntoNet, StaysInTheGoalAndNeverGoesBehindTheNet) {
  World world(FieldDef{}, PhysicsDef{});
  const Field& field = world.field();
  const float aim_y = GetParam(); // where the shot would cross the back of the net
  const float back_x = -field.half_length() - field.def().goal_depth_mm;
  const float dx = back_x + 2000, dy = aim_y;
  const float v = 8000 / std::hypot(dx, dy);
  world.place_ball(-2000, 0, dx * v, dy * v); // 8 m/s
  float min_x = 0;
  for (int t = 0; t < 500; ++t) {
    run(world, 1);
    min_x = std::min(min_x, world.ball().x_mm);
  }
  const BallTruth b = world.ball();
  EXPECT_TRUE(field.in_goal(0, b.x_mm, b.y_mm)) << b.x_mm << ", " << b.y_mm;
  EXPECT_GT(min_x, back_x + world.physics().ball_diameter_mm / 2 - 1) << "went through the net";
}

INSTANTIATE_TEST_SUITE_P(Aims, ShotIntoNet, ::testing::Values(0.f, 400.f, -600.f));

TEST(World, WallsKeepTheBallOnTheCarpet) {
  for (int k = 0; k < 16; ++k) {
    World world(FieldDef{}, PhysicsDef{});
    const float dir = 0.1f + static_cast<float>(k) * 2 * kPi / 16;
    world.place_ball(200, -100, 10000 * std::cos(dir), 10000 * std::sin(dir));
    const float r = world.physics().ball_diameter_mm / 2;
    // At the time of impact Box2D lets a bullet overlap by up to 3 linear slops (15 mm)
    // before pushing it out; the centre never leaves the carpet.
    const float reach = r - 15;
    for (int t = 0; t < 600; ++t) {
      run(world, 1);
      const BallTruth b = world.ball();
      ASSERT_TRUE(world.field().on_carpet(b.x_mm, b.y_mm)) << "direction " << k;
      ASSERT_LE(std::fabs(b.x_mm), world.field().half_length() + 700 - reach) << "direction " << k;
      ASSERT_LE(std::fabs(b.y_mm), world.field().half_width() + 700 - reach) << "direction " << k;
    }
  }
}

// --- contacts with feet -----------------------------------------------------------------

TEST(World, AMovingFootKicksTheBall) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-500, 0, 0});
  const RobotTruth r = world.robot(0);
  const float toe = r.left_foot.x_mm + world.physics().foot_length_mm / 2;
  const float ball_x = toe + world.physics().ball_diameter_mm / 2 + 20;
  world.place_ball(ball_x, r.left_foot.y_mm);
  TickMotion swing;
  swing.left.dx_mm = 15; // 1.5 m/s
  for (int t = 0; t < 6; ++t) world.step({swing});
  EXPECT_GT(world.ball().vx_mm_s, 1500) << "the ball should leave faster than the foot";
  run(world, 50);
  EXPECT_GT(world.ball().x_mm, ball_x + 500);
  EXPECT_NEAR(world.ball().y_mm, r.left_foot.y_mm, 5);
}

TEST(World, RemembersWhichRobotTouchedTheBallLast) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-500, 0, 0});
  world.add_robot(kBlue1, Pose2D{1500, 1000, kPi});
  EXPECT_EQ(world.last_ball_touch(), -1);
  const float ball_x = world.robot(0).left_foot.x_mm + world.physics().foot_length_mm / 2 + 40;
  world.place_ball(ball_x, world.robot(0).left_foot.y_mm);
  TickMotion swing;
  swing.left.dx_mm = 15;
  for (int t = 0; t < 6; ++t) world.step({swing, TickMotion{}});
  EXPECT_EQ(world.last_ball_touch(), 0);
  // Now roll it into the other robot's foot.
  const RobotTruth blue = world.robot(1);
  world.place_ball(blue.right_foot.x_mm - 300, blue.right_foot.y_mm, 2000, 0);
  run(world, 30);
  EXPECT_EQ(world.last_ball_touch(), 1);
}

TEST(World, ReportsTheRobotsWhoseFeetBeganTouchingTheBallInEachStep) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-500, 0, 0});
  world.add_robot(kBlue1, Pose2D{1500, 1000, kPi});
  const float ball_x = world.robot(0).left_foot.x_mm + world.physics().foot_length_mm / 2 + 40;
  world.place_ball(ball_x, world.robot(0).left_foot.y_mm);
  TickMotion swing;
  swing.left.dx_mm = 15;
  std::vector<int> touches;
  for (int t = 0; t < 6; ++t) {
    world.step({swing, TickMotion{}});
    touches.insert(touches.end(), world.ball_touches().begin(), world.ball_touches().end());
  }
  EXPECT_EQ(touches, std::vector<int>{0}); // one touch, when the contact began
  world.step({TickMotion{}, TickMotion{}});
  EXPECT_TRUE(world.ball_touches().empty()); // cleared by the next step
  EXPECT_EQ(world.last_ball_touch(), 0);     // while the last toucher is remembered
}

class StandingFoot : public ::testing::TestWithParam<int> {};

TEST_P(StandingFoot, YieldsOnlyForTheSubstepOfTheHitAndStaysPut) {
  PhysicsDef physics;
  physics.substeps = GetParam();
  World world(FieldDef{}, physics);
  world.add_robot(kRed1, Pose2D{0, 0, 0});
  const RobotTruth before = world.robot(0);
  const float v_in = 10000;
  world.place_ball(600, before.left_foot.y_mm, -v_in, 0);
  run(world, 20);
  const float v_out = world.ball().vx_mm_s;
  EXPECT_GT(v_out, 0) << "the ball bounces off the foot";
  // The hit's momentum moves the foot for one substep, then the (zero) command is
  // re-imposed: it yields m_ball (v_in + v_out) / m_foot * h, not a whole tick's worth.
  const float h = 0.01f / static_cast<float>(physics.substeps);
  const float yield = physics.ball_mass_kg * (v_in + v_out) / physics.foot_mass_kg * h;
  const RobotTruth hit = world.robot(0);
  EXPECT_LT(std::fabs(hit.left_foot.x_mm - before.left_foot.x_mm), 1.3f * yield);
  run(world, 50);
  EXPECT_EQ(world.robot(0).left_foot.x_mm, hit.left_foot.x_mm) << "drifted after the hit";
}

INSTANTIATE_TEST_SUITE_P(Substeps, StandingFoot, ::testing::Values(1, 2, 8));

struct TunnelCase {
  float speed_mm_s;
  int substeps;
};

class NoTunnelling : public ::testing::TestWithParam<TunnelCase> {};

TEST_P(NoTunnelling, AFastBallNeverPassesThroughAThinFoot) {
  PhysicsDef physics;
  physics.substeps = GetParam().substeps;
  physics.foot_width_mm = 40; // thinner than the ball's travel in one step at 30 m/s
  World world(FieldDef{}, physics, 1000.f);
  // Left foot at (-500, 1500), its 40 mm width along the ball's path (clear of the goal).
  world.add_robot(kRed1, Pose2D{0, 1500, kPi / 2});
  world.place_ball(-1500, 1500, GetParam().speed_mm_s, 0);
  bool bounced = false;
  for (int t = 0; t < 40; ++t) {
    run(world, 1);
    ASSERT_LT(world.ball().x_mm, world.robot(0).left_foot.x_mm) << "tick " << t;
    bounced = bounced || world.ball().vx_mm_s < 0;
  }
  EXPECT_TRUE(bounced);
}

INSTANTIATE_TEST_SUITE_P(Speeds, NoTunnelling,
                         ::testing::Values(TunnelCase{10000, 2}, TunnelCase{10000, 1},
                                           TunnelCase{30000, 2}, TunnelCase{30000, 1}));

TEST(World, RobotsWalkingIntoEachOtherDoNotPassThrough) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-300, 0, 0});
  park_ball(world);
  world.add_robot(kBlue1, Pose2D{300, 0, kPi}); // facing each other
  TickMotion forward;
  forward.left.dx_mm = forward.right.dx_mm = 5; // 0.5 m/s each
  const PhysicsDef& p = world.physics();
  float worst = 0;
  for (int t = 0; t < 200; ++t) { // 1 m each, if nothing were in the way
    world.step({forward, forward});
    const RobotTruth a = world.robot(0), b = world.robot(1);
    for (const Pose2D& fa : {a.left_foot, a.right_foot})
      for (const Pose2D& fb : {b.left_foot, b.right_foot})
        worst = std::max(worst, overlap_depth(fa, fb, p.foot_length_mm, p.foot_width_mm));
  }
  // Box2D keeps pressed contacts overlapping by its linear slop, 5 mm.
  EXPECT_LT(worst, 5.5f) << "feet overlapped by " << worst << " mm";
  const RobotTruth a = world.robot(0), b = world.robot(1);
  EXPECT_LT(a.body.x_mm, b.body.x_mm);
  EXPECT_GT(a.body.x_mm, -300 + 100); // it did walk until they met ...
  EXPECT_LT(a.body.x_mm, 0);          // ... and no further
}

TEST(World, ARobotPushesAStandingOne) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-300, 0, 0});
  park_ball(world);
  world.add_robot(kBlue1, Pose2D{0, 0, kPi});
  TickMotion forward;
  forward.left.dx_mm = forward.right.dx_mm = 5;
  const PhysicsDef& p = world.physics();
  float worst = 0;
  for (int t = 0; t < 200; ++t) {
    world.step({forward, TickMotion{}});
    const RobotTruth a = world.robot(0), b = world.robot(1);
    for (const Pose2D& fa : {a.left_foot, a.right_foot})
      for (const Pose2D& fb : {b.left_foot, b.right_foot})
        worst = std::max(worst, overlap_depth(fa, fb, p.foot_length_mm, p.foot_width_mm));
  }
  EXPECT_LT(worst, 5.5f);
  EXPECT_GT(world.robot(1).body.x_mm, 100) << "the standing robot was pushed back";
  EXPECT_LT(world.robot(0).body.x_mm, world.robot(1).body.x_mm);
}

// --- determinism ------------------------------------------------------------------------

/// A busy scene: four robots around the ball, kicked off at 3 m/s.
void set_up_scene(World& world) {
  world.add_robot(kRed1, Pose2D{-400, 0, 0});
  world.add_robot(RobotId{0, 2}, Pose2D{-200, 400, -1});
  world.add_robot(kBlue1, Pose2D{400, 0, kPi});
  world.add_robot(RobotId{1, 2}, Pose2D{200, -400, 2});
  world.place_ball(0, 0, 2000, 2200);
}

std::vector<std::vector<TickMotion>> random_motions(int ticks, int robots, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> step(-8, 8), side(-5, 5), turn(-0.04f, 0.04f);
  std::vector<std::vector<TickMotion>> all(static_cast<std::size_t>(ticks), still(robots));
  for (auto& tick : all)
    for (auto& m : tick) {
      m.left = FootMotion{step(rng), side(rng), turn(rng)};
      m.right = FootMotion{step(rng), side(rng), turn(rng)};
    }
  return all;
}

TEST(World, SameMotionsGiveTheSameHashAndOneDifferentMotionDoesNot) {
  const auto motions = random_motions(3000, 4, 20110704u);
  auto changed = motions;
  changed[1500][2].right.dx_mm += 0.5f;

  World a(FieldDef{}, PhysicsDef{}), b(FieldDef{}, PhysicsDef{}), c(FieldDef{}, PhysicsDef{});
  for (World* w : {&a, &b, &c}) set_up_scene(*w);
  ASSERT_EQ(a.state_hash(), c.state_hash());
  for (std::size_t t = 0; t < motions.size(); ++t) {
    a.step(motions[t]);
    b.step(motions[t]);
    c.step(changed[t]);
    ASSERT_EQ(a.state_hash(), b.state_hash()) << "diverged at tick " << t;
  }
  EXPECT_NE(a.state_hash(), c.state_hash());
  EXPECT_EQ(a.ticks(), 3000);
}

TEST(World, HashSeesEveryPartOfTheState) {
  World a(FieldDef{}, PhysicsDef{}), b(FieldDef{}, PhysicsDef{});
  set_up_scene(a);
  set_up_scene(b);
  EXPECT_EQ(a.state_hash(), b.state_hash());
  b.place_ball(0, 0, 2000, 2200.001f); // velocity only
  EXPECT_NE(a.state_hash(), b.state_hash());
  b.place_ball(0, 0, 2000, 2200);
  b.place_robot(3, Pose2D{200, -400, 2.0001f}); // a foot angle only
  EXPECT_NE(a.state_hash(), b.state_hash());
  b.place_robot(3, Pose2D{200, -400, 2});
  EXPECT_EQ(a.state_hash(), b.state_hash());
}

TEST(World, HashCountsTicksEvenWhenNothingMoves) {
  World world(FieldDef{}, PhysicsDef{});
  world.add_robot(kRed1, Pose2D{-1000, 0, 0});
  world.place_ball(1000, 0);
  const uint64_t before = world.state_hash();
  const RobotTruth r = world.robot(0);
  world.step(still(1));
  EXPECT_EQ(world.robot(0).left_foot.x_mm, r.left_foot.x_mm);
  EXPECT_EQ(world.ball().x_mm, 1000.f);
  EXPECT_NE(world.state_hash(), before);
}

} // namespace
} // namespace touchline::sim
