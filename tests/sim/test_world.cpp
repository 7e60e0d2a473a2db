// The physical world: feet move as commanded, the ball rolls, bounces and stops as the
// model says, contacts are physical, and the same inputs give the same world.
#include "touchline/sim/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "touchline/angles.hpp"

namespace touchline::sim {
namespace {

constexpr RobotId kRed1{0, 1};
constexpr RobotId kBlue1{1, 1};

std::vector<TickMotion> still(int robots) { return std::vector<TickMotion>(static_cast<std::size_t>(robots)); }

void run(World& world, int ticks) {
  for (int t = 0; t < ticks; ++t) world.step(still(world.robot_count()));
}

/// The ball starts at the centre spot; tests about feet move it out of their way.
void park_ball(World& world) { world.place_ball(2500, -2200); }

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
