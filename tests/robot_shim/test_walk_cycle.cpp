// WalkCycle: standing, gait timing, symmetry, limits, odometry accuracy, stopping, feet
// that never cross, and the per-tick foot motions the world receives.
#include "touchline/robot/walk_cycle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "touchline/angles.hpp"

namespace touchline::robot {
namespace {

constexpr float kDt = 0.01f;           // the 100 Hz motion tick
constexpr int kTicksPerSecond = 100;
const WalkDef kDef{};                  // the default walk
const int kTicksPerStep = static_cast<int>(std::lround(kDef.period_s / 2 / kDt));

bool same_pose(const Pose2D& a, const Pose2D& b) {
  return a.x_mm == b.x_mm && a.y_mm == b.y_mm && a.theta_rad == b.theta_rad;
}

bool same_feet(const FeetPose& a, const FeetPose& b) {
  return same_pose(a.left, b.left) && same_pose(a.right, b.right);
}

/// `p` seen from `body`: (forward, left) in the body frame.
Pose2D in_body_frame(const Pose2D& p, const Pose2D& body) {
  const float dx = p.x_mm - body.x_mm, dy = p.y_mm - body.y_mm;
  const float c = std::cos(body.theta_rad), s = std::sin(body.theta_rad);
  return {c * dx + s * dy, -s * dx + c * dy, normalise_angle(p.theta_rad - body.theta_rad)};
}

/// Midpoint and circular mean heading, computed independently of the walk's own helpers.
Pose2D expected_body(const FeetPose& f) {
  return {(f.left.x_mm + f.right.x_mm) / 2, (f.left.y_mm + f.right.y_mm) / 2,
          std::atan2(std::sin(f.left.theta_rad) + std::sin(f.right.theta_rad),
                     std::cos(f.left.theta_rad) + std::cos(f.right.theta_rad))};
}

/// Left foot's lateral offset from the right foot, in the body frame (> 0: not crossed).
float lateral_separation(const FeetPose& f) {
  const Pose2D body = expected_body(f);
  return in_body_frame(f.left, body).y_mm - in_body_frame(f.right, body).y_mm;
}

void run(WalkCycle& walk, const WalkRequest& request, int ticks) {
  for (int i = 0; i < ticks; ++i) walk.tick(request, kDt);
}

/// Heading with its wraps undone, followed tick by tick.
struct UnwrappedHeading {
  float last = 0;
  float total = 0;
  void update(float heading) {
    total += normalise_angle(heading - last);
    last = heading;
  }
};

// ---------------------------------------------------------------------------- standing

TEST(WalkCycleStanding, ResetPutsFeetSideBySideAroundOrigin) {
  WalkCycle walk;
  EXPECT_FLOAT_EQ(walk.feet().left.x_mm, 0);
  EXPECT_FLOAT_EQ(walk.feet().left.y_mm, kDef.foot_separation_mm / 2);
  EXPECT_FLOAT_EQ(walk.feet().right.x_mm, 0);
  EXPECT_FLOAT_EQ(walk.feet().right.y_mm, -kDef.foot_separation_mm / 2);
  EXPECT_EQ(walk.feet().left.theta_rad, 0);
  EXPECT_EQ(walk.feet().right.theta_rad, 0);
  EXPECT_TRUE(walk.standing());
}

TEST(WalkCycleStanding, ZeroRequestFromResetMovesNothing) {
  WalkCycle walk;
  const FeetPose start = walk.feet();
  for (int i = 0; i < 100; ++i) {
    walk.tick({}, kDt);
    ASSERT_TRUE(same_feet(walk.feet(), start)) << "tick " << i;
    ASSERT_TRUE(walk.standing());
    ASSERT_EQ(walk.phase_s(), 0);
    ASSERT_EQ(walk.velocity().forward_mm_s, 0);
  }
}

TEST(WalkCycleStanding, ResetAfterWalkingStandsAtOriginAgain) {
  WalkCycle walk;
  run(walk, {200, 50, 0.5f}, 123);
  ASSERT_FALSE(walk.standing());
  walk.reset();
  EXPECT_TRUE(walk.standing());
  EXPECT_EQ(walk.phase_s(), 0);
  EXPECT_FLOAT_EQ(walk.odometry().x_mm, 0);
  EXPECT_FLOAT_EQ(walk.odometry().y_mm, 0);
  EXPECT_EQ(walk.velocity().forward_mm_s, 0);
}

TEST(WalkCycleStanding, NonFiniteRequestIsTreatedAsZero) {
  WalkCycle walk;
  const float nan = std::nanf("");
  run(walk, {nan, std::numeric_limits<float>::infinity(), nan}, 100);
  EXPECT_TRUE(walk.standing());
  run(walk, {nan, 200, 0}, 100); // the finite axis still walks
  EXPECT_GT(walk.odometry().y_mm, 10);
  EXPECT_EQ(walk.odometry().x_mm, 0);
}

// --------------------------------------------------------------------- lead foot, steps

/// Which foot moves first from standing; the other must not move during that step.
std::string first_mover(const WalkRequest& request) {
  WalkCycle walk;
  const FeetPose start = walk.feet();
  run(walk, request, kTicksPerStep - 1);
  const bool left_moved = !same_pose(walk.feet().left, start.left);
  const bool right_moved = !same_pose(walk.feet().right, start.right);
  if (left_moved && right_moved) return "both";
  return left_moved ? "left" : right_moved ? "right" : "none";
}

TEST(WalkCycleLead, FirstStepIsTakenByTheFootOnTheSideOfTravel) {
  EXPECT_EQ(first_mover({300, 0, 0}), "left");
  EXPECT_EQ(first_mover({-200, 0, 0}), "left");
  EXPECT_EQ(first_mover({0, 200, 0}), "left");
  EXPECT_EQ(first_mover({0, -200, 0}), "right");
  EXPECT_EQ(first_mover({0, 0, 1}), "left");
  EXPECT_EQ(first_mover({0, 0, -1}), "right");
  EXPECT_EQ(first_mover({100, -50, 1}), "right"); // sideways decides before turning
}

TEST(WalkCycleSteps, FullSpeedForwardStepsAreVelocityTimesPeriod) {
  WalkCycle walk;
  run(walk, {300, 0, 0}, 2 * kTicksPerSecond + 1); // steady, one tick into a step
  const StepParams& step = walk.step();
  const float expected = 300 * kDef.period_s; // 150 mm per foot per cycle
  const float swing_forward = walk.left_swinging() ? step.forward_left_mm : step.forward_right_mm;
  const float stance_forward = walk.left_swinging() ? step.forward_right_mm : step.forward_left_mm;
  EXPECT_NEAR(swing_forward, expected, 0.01f * expected);
  EXPECT_EQ(stance_forward, 0);
  EXPECT_NEAR(step.left_mm, 0, 1e-3f);
  EXPECT_NEAR(step.turn_rad, 0, 1e-6f);
}

TEST(WalkCycleSteps, TurningInPlaceSwingFootTurnsRateTimesPeriod) {
  WalkCycle walk;
  run(walk, {0, 0, kDef.max_turn_rad_s}, 2 * kTicksPerSecond + 1);
  EXPECT_NEAR(walk.step().turn_rad, kDef.max_turn_rad_s * kDef.period_s, 1e-3f);
}

// --------------------------------------------------------------------------- period

TEST(WalkCyclePeriod, SwingFootAlternatesEveryHalfPeriodAndPhaseWrapsAtPeriod) {
  WalkCycle walk;
  const WalkRequest request{300, 0, 0};
  run(walk, request, 2 * kTicksPerSecond); // steady speed
  int wraps = 0;
  float last_phase = walk.phase_s();
  std::vector<char> mover; // per tick: 'L', 'R' or '-' (both feet down)
  for (int i = 0; i < 4 * kTicksPerSecond; ++i) {
    const FeetPose before = walk.feet();
    walk.tick(request, kDt);
    const bool left_moved = !same_pose(walk.feet().left, before.left);
    const bool right_moved = !same_pose(walk.feet().right, before.right);
    ASSERT_FALSE(left_moved && right_moved) << "both feet moved at tick " << i;
    ASSERT_GE(walk.phase_s(), 0);
    ASSERT_LT(walk.phase_s(), kDef.period_s);
    if (walk.phase_s() < last_phase) ++wraps;
    last_phase = walk.phase_s();
    if (left_moved || right_moved) {
      // The foot that moves is the one the phase says swings: left in [0, T/2).
      ASSERT_EQ(left_moved, walk.left_swinging()) << "tick " << i;
      ASSERT_EQ(left_moved, walk.phase_s() < kDef.period_s / 2) << "tick " << i;
    }
    mover.push_back(left_moved ? 'L' : right_moved ? 'R' : '-');
  }
  EXPECT_EQ(wraps, 8); // 4 s of 0.5 s cycles

  // Group the moving ticks into swings: each swing is one foot, swings alternate, and
  // consecutive swings start exactly T/2 apart.
  std::vector<std::pair<int, char>> swing_starts;
  for (size_t i = 0; i < mover.size(); ++i)
    if (mover[i] != '-' && (i == 0 || mover[i - 1] != mover[i]))
      swing_starts.emplace_back(static_cast<int>(i), mover[i]);
  ASSERT_GE(swing_starts.size(), 15u);
  for (size_t k = 2; k < swing_starts.size(); ++k) { // the first may be cut by the window
    EXPECT_NE(swing_starts[k].second, swing_starts[k - 1].second);
    EXPECT_EQ(swing_starts[k].first - swing_starts[k - 1].first, kTicksPerStep);
  }
}

TEST(WalkCyclePeriod, DoubleSupportKeepsBothFeetDownAtEachEndOfTheStep) {
  // Default walk: 25 ticks a step, double support 20% = 2.5 ticks at each end. Ticks
  // ending 0.01 and 0.02 s into the step are before lift-off; the tick ending 0.24 s and
  // the one ending the step are after landing (0.225 s); ticks 3..22 all swing.
  ASSERT_EQ(kTicksPerStep, 25);
  ASSERT_EQ(kDef.double_support, 0.2f);
  WalkCycle walk;
  const WalkRequest request{300, 0, 0};
  run(walk, request, 2 * kTicksPerSecond);
  for (int i = 0; i < 4 * kTicksPerStep; ++i) {
    const FeetPose before = walk.feet();
    walk.tick(request, kDt);
    const bool moved = !same_feet(before, walk.feet());
    const float into_step = std::fmod(walk.phase_s(), kDef.period_s / 2);
    const int k = static_cast<int>(std::lround(into_step / kDt)); // 0: the step just ended
    if (k == 0 || k == 1 || k == 2 || k == 24) {
      EXPECT_FALSE(moved) << "tick " << k << " of the step";
    } else if (k >= 3 && k <= 22) {
      EXPECT_TRUE(moved) << "tick " << k << " of the step";
    }
  }
}

/// Forward distance the swing foot covers in each tick of one steady step.
std::vector<float> swing_increments(float swing_shape) {
  WalkDef def;
  def.swing_shape = swing_shape;
  WalkCycle walk(def);
  const WalkRequest request{300, 0, 0};
  run(walk, request, 2 * kTicksPerSecond); // steady, at the start of a left step
  std::vector<float> increments;
  for (int i = 0; i < kTicksPerStep; ++i) {
    const float before = walk.feet().left.x_mm;
    walk.tick(request, kDt);
    if (walk.feet().left.x_mm != before) increments.push_back(walk.feet().left.x_mm - before);
  }
  return increments;
}

TEST(WalkCycleSwingShape, ZeroSwingsAtConstantSpeed) {
  const std::vector<float> inc = swing_increments(0);
  ASSERT_GE(inc.size(), 15u);
  // Inner ticks lie wholly inside single support: equal steps.
  for (size_t i = 2; i + 2 < inc.size(); ++i) EXPECT_NEAR(inc[i], inc[inc.size() / 2], 1e-2f);
}

TEST(WalkCycleSwingShape, OneEasesInAndOut) {
  const std::vector<float> inc = swing_increments(1);
  ASSERT_GE(inc.size(), 15u);
  const float peak = *std::max_element(inc.begin(), inc.end());
  EXPECT_LT(inc.front(), 0.25f * peak); // slow lift-off
  EXPECT_LT(inc.back(), 0.25f * peak);  // slow landing
  EXPECT_NEAR(inc[inc.size() / 2], peak, 0.05f * peak);
}

// ------------------------------------------------------------------------- symmetry

Pose2D mirrored(const Pose2D& p) { return {p.x_mm, -p.y_mm, -p.theta_rad}; }

void expect_near_pose(const Pose2D& a, const Pose2D& b, float tol_mm, const std::string& what) {
  EXPECT_NEAR(a.x_mm, b.x_mm, tol_mm) << what;
  EXPECT_NEAR(a.y_mm, b.y_mm, tol_mm) << what;
  EXPECT_NEAR(normalise_angle(a.theta_rad - b.theta_rad), 0, 1e-4f) << what;
}

TEST(WalkCycleSymmetry, WalkingStraightTheFeetMirrorHalfAPeriodApart) {
  WalkCycle walk;
  const float v = 300;
  const WalkRequest request{v, 0, 0};
  run(walk, request, 2 * kTicksPerSecond);
  std::vector<FeetPose> track;
  for (int i = 0; i < kTicksPerSecond; ++i) {
    walk.tick(request, kDt);
    track.push_back(walk.feet());
  }
  const float half_cycle_advance = v * kDef.period_s / 2;
  for (size_t i = 0; i + kTicksPerStep < track.size(); ++i) {
    const Pose2D& left = track[i].left;
    const Pose2D& right_later = track[i + kTicksPerStep].right;
    EXPECT_NEAR(right_later.x_mm, left.x_mm + half_cycle_advance, 0.05f) << "tick " << i;
    EXPECT_NEAR(right_later.y_mm, -left.y_mm, 0.01f) << "tick " << i;
    EXPECT_NEAR(right_later.theta_rad, -left.theta_rad, 1e-6f) << "tick " << i;
  }
}

/// Walks `a` and `b` side by side through the same schedule and expects each foot of one
/// to mirror (y and heading negated) the other foot of the other, tick by tick,
/// through start, steady walking and stopping.
void expect_mirror_walks(const WalkRequest& a, const WalkRequest& b) {
  WalkCycle walk_a, walk_b;
  for (int i = 0; i < 6 * kTicksPerSecond; ++i) {
    const bool go = i < 4 * kTicksPerSecond;
    walk_a.tick(go ? a : WalkRequest{}, kDt);
    walk_b.tick(go ? b : WalkRequest{}, kDt);
    const std::string at = "tick " + std::to_string(i);
    expect_near_pose(walk_a.feet().left, mirrored(walk_b.feet().right), 0.05f, at + " left/right");
    expect_near_pose(walk_a.feet().right, mirrored(walk_b.feet().left), 0.05f, at + " right/left");
    ASSERT_EQ(walk_a.standing(), walk_b.standing()) << at;
    if (!walk_a.standing()) {
      ASSERT_NE(walk_a.left_swinging(), walk_b.left_swinging()) << at;
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_TRUE(walk_a.standing());
}

TEST(WalkCycleSymmetry, WalkingLeftMirrorsWalkingRight) {
  expect_mirror_walks({0, 200, 0}, {0, -200, 0});
}

TEST(WalkCycleSymmetry, TurningLeftMirrorsTurningRight) {
  expect_mirror_walks({0, 0, 1.5f}, {0, 0, -1.5f});
}

TEST(WalkCycleSymmetry, ArcLeftMirrorsArcRight) {
  expect_mirror_walks({250, 80, 0.8f}, {250, -80, -0.8f});
}

// --------------------------------------------------------------------------- limits

TEST(WalkCycleLimits, VelocityNeverExceedsTheLimits) {
  WalkCycle walk;
  const WalkRequest too_fast[] = {{1e4f, 1e4f, 100}, {-1e4f, -1e4f, -100}, {1e4f, -1e4f, 100}};
  for (const WalkRequest& request : too_fast) {
    for (int i = 0; i < 3 * kTicksPerSecond; ++i) {
      walk.tick(request, kDt);
      const WalkRequest& v = walk.velocity();
      ASSERT_LE(v.forward_mm_s, kDef.max_forward_mm_s);
      ASSERT_GE(v.forward_mm_s, -kDef.max_backward_mm_s);
      ASSERT_LE(std::abs(v.left_mm_s), kDef.max_left_mm_s);
      ASSERT_LE(std::abs(v.turn_rad_s), kDef.max_turn_rad_s);
    }
  }
}

struct AxisCase {
  const char* name;
  WalkRequest request;   ///< far beyond the limit on one axis
  float limit;           ///< expected steady speed, signed (mm/s or rad/s)
  float accel;           ///< acceleration limit on that axis
  int axis;              ///< 0 forward, 1 left, 2 turn
};

const AxisCase kAxes[] = {
    {"forward", {1e4f, 0, 0}, kDef.max_forward_mm_s, kDef.accel_forward_mm_s2, 0},
    {"backward", {-1e4f, 0, 0}, -kDef.max_backward_mm_s, kDef.accel_forward_mm_s2, 0},
    {"left", {0, 1e4f, 0}, kDef.max_left_mm_s, kDef.accel_left_mm_s2, 1},
    {"right", {0, -1e4f, 0}, -kDef.max_left_mm_s, kDef.accel_left_mm_s2, 1},
    {"turn_left", {0, 0, 100}, kDef.max_turn_rad_s, kDef.accel_turn_rad_s2, 2},
    {"turn_right", {0, 0, -100}, -kDef.max_turn_rad_s, kDef.accel_turn_rad_s2, 2},
};

class WalkCycleAxis : public ::testing::TestWithParam<AxisCase> {};

float along_axis(const Pose2D& p, float unwrapped_heading, int axis) {
  return axis == 0 ? p.x_mm : axis == 1 ? p.y_mm : unwrapped_heading;
}

TEST_P(WalkCycleAxis, SteadyOdometrySpeedOverACycleIsTheClampedRequest) {
  const AxisCase& c = GetParam();
  WalkCycle walk;
  UnwrappedHeading heading;
  const int cycle_ticks = 2 * kTicksPerStep;
  auto advance = [&](int ticks) {
    for (int i = 0; i < ticks; ++i) {
      walk.tick(c.request, kDt);
      heading.update(walk.odometry().theta_rad);
    }
  };
  advance(3 * kTicksPerSecond);
  const float start = along_axis(walk.odometry(), heading.total, c.axis);
  advance(cycle_ticks);
  const float speed = (along_axis(walk.odometry(), heading.total, c.axis) - start) / kDef.period_s;
  // Turning rotates the body frame, so only the heading is an axis of the odometry frame.
  EXPECT_NEAR(speed, c.limit, 0.02f * std::abs(c.limit)) << c.name;
}

TEST_P(WalkCycleAxis, DistanceAfterTenSecondsMatchesTheAccelerationRamp) {
  const AxisCase& c = GetParam();
  WalkCycle walk;
  UnwrappedHeading heading;
  float max_drift_mm = 0; // turning: distance from the start; otherwise: off-axis distance
  float max_heading_drift = 0;
  for (int i = 0; i < 10 * kTicksPerSecond; ++i) {
    walk.tick(c.request, kDt);
    heading.update(walk.odometry().theta_rad);
    const Pose2D& o = walk.odometry();
    const float drift = c.axis == 2 ? std::hypot(o.x_mm, o.y_mm)
                                    : std::abs(c.axis == 0 ? o.y_mm : o.x_mm);
    max_drift_mm = std::max(max_drift_mm, drift);
    if (c.axis != 2) max_heading_drift = std::max(max_heading_drift, std::abs(o.theta_rad));
  }
  const float v = std::abs(c.limit), t = 10;
  const float nominal = std::copysign(v * (t - v / (2 * c.accel)), c.limit);
  const float measured = along_axis(walk.odometry(), heading.total, c.axis);
  std::printf("[ measured ] %-10s after 10 s: %9.3f vs nominal %9.3f (%+.3f%%), max drift %.2f mm\n",
              c.name, measured, nominal, 100 * (measured - nominal) / nominal, max_drift_mm);
  EXPECT_NEAR(measured, nominal, 0.03f * std::abs(nominal)) << c.name;
  if (c.axis == 2) {
    EXPECT_LT(max_drift_mm, 0.25f * kDef.foot_separation_mm) << "turning in place wanders";
  } else {
    EXPECT_LT(max_drift_mm, 0.5f) << "straight walking leaves its line";
    EXPECT_LT(max_heading_drift, 1e-4f) << "straight walking turns";
  }
}

INSTANTIATE_TEST_SUITE_P(Axes, WalkCycleAxis, ::testing::ValuesIn(kAxes),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(WalkCycleAcceleration, OdometryStaysWithinATenthOfAStepOfTheVelocityIntegral) {
  // The feet land half a step ahead of the body, so the body (their midpoint) follows
  // the integral of velocity() tick by tick, off only by the steps' own unevenness.
  for (const WalkRequest& request : {WalkRequest{1e4f, 0, 0}, WalkRequest{0, -1e4f, 0}}) {
    WalkCycle walk;
    float travelled = 0, worst = 0;
    for (int i = 0; i < 10 * kTicksPerSecond; ++i) {
      const WalkRequest before = walk.velocity();
      walk.tick(request, kDt);
      const bool forward = request.forward_mm_s != 0;
      travelled += 0.5f * kDt * (forward ? before.forward_mm_s + walk.velocity().forward_mm_s
                                         : before.left_mm_s + walk.velocity().left_mm_s);
      const float odometry = forward ? walk.odometry().x_mm : walk.odometry().y_mm;
      worst = std::max(worst, std::abs(odometry - travelled));
    }
    std::printf("[ measured ] odometry vs velocity integral: worst %.2f mm\n", worst);
    EXPECT_LT(worst, 0.1f * kDef.max_forward_mm_s * kDef.period_s);
  }
}

TEST(WalkCycleAcceleration, VelocityChangesAtMostAccelTimesDtPerTick) {
  WalkCycle walk;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.5f, 1.5f);
  WalkRequest request;
  for (int i = 0; i < 20 * kTicksPerSecond; ++i) {
    if (i % 37 == 0)
      request = {unit(rng) * kDef.max_forward_mm_s, unit(rng) * kDef.max_left_mm_s,
                 unit(rng) * kDef.max_turn_rad_s};
    const WalkRequest before = walk.velocity();
    walk.tick(request, kDt);
    const WalkRequest& after = walk.velocity();
    const float slack = 1e-3f;
    ASSERT_LE(std::abs(after.forward_mm_s - before.forward_mm_s),
              kDef.accel_forward_mm_s2 * kDt + slack) << "tick " << i;
    ASSERT_LE(std::abs(after.left_mm_s - before.left_mm_s), kDef.accel_left_mm_s2 * kDt + slack)
        << "tick " << i;
    ASSERT_LE(std::abs(after.turn_rad_s - before.turn_rad_s), kDef.accel_turn_rad_s2 * kDt + 1e-5f)
        << "tick " << i;
  }
}

// ------------------------------------------------------------------------- stopping

struct StopCase {
  const char* name;
  WalkRequest request;
};

class WalkCycleStop : public ::testing::TestWithParam<StopCase> {};

TEST_P(WalkCycleStop, FeetEndSquareAndStillWithinAPeriodPlusDeceleration) {
  const StopCase& c = GetParam();
  WalkCycle walk;
  run(walk, c.request, 3 * kTicksPerSecond + 7); // stop somewhere inside a step
  const WalkRequest v = walk.velocity();
  const float decel_s = std::max({std::abs(v.forward_mm_s) / kDef.accel_forward_mm_s2,
                                  std::abs(v.left_mm_s) / kDef.accel_left_mm_s2,
                                  std::abs(v.turn_rad_s) / kDef.accel_turn_rad_s2});
  // The step in progress finishes as planned, then deceleration, then at most a
  // cycle to bring the feet together.
  const int allowed = static_cast<int>(std::ceil((decel_s + 1.5f * kDef.period_s) / kDt)) + 1;
  int ticks = 0;
  FeetPose before_last_tick = walk.feet();
  while (!walk.standing() && ticks < 10 * kTicksPerSecond) {
    before_last_tick = walk.feet();
    walk.tick({}, kDt);
    ++ticks;
  }
  std::printf("[ measured ] stop %-9s standing after %.2f s (deceleration %.2f s)\n", c.name,
              static_cast<double>(ticks) * kDt, decel_s);
  ASSERT_TRUE(walk.standing()) << c.name;
  EXPECT_LE(ticks, allowed) << c.name;
  // The feet were already at rest when the walk stood: no jump on the last tick.
  FootMotion last_left, last_right;
  feet_motion(before_last_tick, walk.feet(), last_left, last_right);
  EXPECT_LT(std::hypot(last_left.dx_mm, last_left.dy_mm), 1e-3f);
  EXPECT_LT(std::hypot(last_right.dx_mm, last_right.dy_mm), 1e-3f);
  EXPECT_LT(std::abs(last_left.dtheta_rad) + std::abs(last_right.dtheta_rad), 1e-5f);

  const FeetPose& f = walk.feet();
  EXPECT_EQ(f.left.theta_rad, f.right.theta_rad) << "feet square";
  const Pose2D left_in_right = in_body_frame(f.left, f.right);
  EXPECT_NEAR(left_in_right.x_mm, 0, 1e-3f) << "side by side";
  EXPECT_NEAR(left_in_right.y_mm, kDef.foot_separation_mm, 1e-3f);
  EXPECT_EQ(walk.phase_s(), 0);
  EXPECT_EQ(walk.velocity().forward_mm_s, 0);
  EXPECT_EQ(walk.step().forward_left_mm, 0);

  for (int i = 0; i < 100; ++i) {
    const FeetPose before = walk.feet();
    walk.tick({}, kDt);
    FootMotion left, right;
    feet_motion(before, walk.feet(), left, right);
    ASSERT_EQ(left.dx_mm, 0);
    ASSERT_EQ(left.dy_mm, 0);
    ASSERT_EQ(left.dtheta_rad, 0);
    ASSERT_EQ(right.dx_mm, 0);
    ASSERT_EQ(right.dy_mm, 0);
    ASSERT_EQ(right.dtheta_rad, 0);
    ASSERT_TRUE(walk.standing());
  }
}

const StopCase kStops[] = {
    {"forward", {300, 0, 0}},   {"backward", {-200, 0, 0}}, {"left", {0, 200, 0}},
    {"right", {0, -200, 0}},    {"turn", {0, 0, -1.5f}},    {"omni", {250, -120, 0.9f}},
    {"creep", {10, 0, 0}},
};
INSTANTIATE_TEST_SUITE_P(Requests, WalkCycleStop, ::testing::ValuesIn(kStops),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(WalkCycleStopping, AZeroRequestInTheFirstStepStillEndsSquare) {
  WalkCycle walk;
  run(walk, {300, 100, 1}, 3);
  run(walk, {}, 2 * kTicksPerSecond);
  ASSERT_TRUE(walk.standing());
  EXPECT_EQ(walk.feet().left.theta_rad, walk.feet().right.theta_rad);
  EXPECT_NEAR(in_body_frame(walk.feet().left, walk.feet().right).y_mm, kDef.foot_separation_mm,
              1e-3f);
}

TEST(WalkCycleStopping, WalksAgainAfterStopping) {
  WalkCycle walk;
  run(walk, {300, 0, 0}, kTicksPerSecond);
  run(walk, {}, 3 * kTicksPerSecond);
  ASSERT_TRUE(walk.standing());
  const float stopped_at = walk.odometry().x_mm;
  run(walk, {300, 0, 0}, kTicksPerSecond);
  EXPECT_FALSE(walk.standing());
  EXPECT_GT(walk.odometry().x_mm, stopped_at + 100);
}

// ---------------------------------------------------------- feet never cross, odometry

TEST(WalkCycleOmni, FeetNeverCrossAndOdometryIsTheFeetMidpointOverSixtySecondsOfRandomWalking) {
  WalkCycle walk;
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<float> unit(-1.2f, 1.2f);
  std::uniform_int_distribution<int> hold_ticks(10, 200);
  std::bernoulli_distribution stop(0.15);
  WalkRequest request;
  int change_at = 0;
  float min_separation = 1e9f, max_separation = 0;
  for (int i = 0; i < 60 * kTicksPerSecond; ++i) {
    if (i == change_at) {
      request = stop(rng) ? WalkRequest{}
                          : WalkRequest{unit(rng) * kDef.max_forward_mm_s,
                                        unit(rng) * kDef.max_left_mm_s,
                                        unit(rng) * kDef.max_turn_rad_s};
      change_at += hold_ticks(rng);
    }
    walk.tick(request, kDt);
    const float separation = lateral_separation(walk.feet());
    min_separation = std::min(min_separation, separation);
    max_separation = std::max(max_separation, separation);
    ASSERT_GT(separation, 0) << "feet crossed at tick " << i;

    const Pose2D expected = expected_body(walk.feet());
    ASSERT_NEAR(walk.odometry().x_mm, expected.x_mm, 1e-3f);
    ASSERT_NEAR(walk.odometry().y_mm, expected.y_mm, 1e-3f);
    ASSERT_NEAR(normalise_angle(walk.odometry().theta_rad - expected.theta_rad), 0, 1e-5f);
  }
  std::printf("[ measured ] random walking: lateral foot separation %.1f .. %.1f mm\n",
              min_separation, max_separation);
}

TEST(WalkCycleOdometry, IsTheMidpointAndMeanHeadingOfTheFeetAcrossTheWrap) {
  // Turn until the feet straddle +-pi: the mean heading must be near pi, not near 0.
  WalkCycle walk;
  bool straddled = false;
  for (int i = 0; i < 5 * kTicksPerSecond && !straddled; ++i) {
    walk.tick({0, 0, 1.5f}, kDt);
    const float a = walk.feet().left.theta_rad, b = walk.feet().right.theta_rad;
    if (a * b < 0 && std::abs(a) > 2.5f) {
      straddled = true;
      EXPECT_GT(std::abs(walk.odometry().theta_rad), 2.5f);
      EXPECT_NEAR(normalise_angle(walk.odometry().theta_rad - expected_body(walk.feet()).theta_rad),
                  0, 1e-5f);
    }
  }
  EXPECT_TRUE(straddled);
}

// ---------------------------------------------------------------------- feet_motion

TEST(WalkCycleFeetMotion, PureTranslation) {
  const FeetPose before{{0, 50, 0}, {0, -50, 0}};
  const FeetPose after{{10, 45, 0}, {3, -50, 0}};
  FootMotion left, right;
  feet_motion(before, after, left, right);
  EXPECT_FLOAT_EQ(left.dx_mm, 10);
  EXPECT_FLOAT_EQ(left.dy_mm, -5);
  EXPECT_FLOAT_EQ(left.dtheta_rad, 0);
  EXPECT_FLOAT_EQ(right.dx_mm, 3);
  EXPECT_FLOAT_EQ(right.dy_mm, 0);
}

TEST(WalkCycleFeetMotion, IsInTheBodyFrameOfTheStartPose) {
  // Body facing +y (pi/2): left foot at -x, right foot at +x.
  const float up = kPi / 2;
  const FeetPose before{{-50, 0, up}, {50, 0, up}};
  // Left foot moves 10 along world +y (body forward), right foot 10 along world +x (body right).
  const FeetPose after{{-50, 10, up + 0.1f}, {60, 0, up}};
  FootMotion left, right;
  feet_motion(before, after, left, right);
  EXPECT_NEAR(left.dx_mm, 10, 1e-4f);
  EXPECT_NEAR(left.dy_mm, 0, 1e-4f);
  EXPECT_NEAR(left.dtheta_rad, 0.1f, 1e-6f);
  EXPECT_NEAR(right.dx_mm, 0, 1e-4f);
  EXPECT_NEAR(right.dy_mm, -10, 1e-4f);
}

TEST(WalkCycleFeetMotion, BodyFrameUsesTheMeanOfBothFeetsHeadings) {
  // Feet at 0.2 and 0.4 rad: the body heading is 0.3 rad.
  const FeetPose before{{0, 50, 0.2f}, {0, -50, 0.4f}};
  const FeetPose after{{std::cos(0.3f) * 20, 50 + std::sin(0.3f) * 20, 0.2f}, {0, -50, 0.4f}};
  FootMotion left, right;
  feet_motion(before, after, left, right);
  EXPECT_NEAR(left.dx_mm, 20, 1e-4f);
  EXPECT_NEAR(left.dy_mm, 0, 1e-4f);
}

TEST(WalkCycleFeetMotion, RotationWrapsAcrossPi) {
  // Both feet face just short of pi; the left foot turns 0.1 rad counter-clockwise, past
  // the wrap, and moves 10 mm along world +x, which is backwards for this body.
  const float facing = kPi - 0.05f;
  const FeetPose before{{0, -50, facing}, {0, 50, facing}};
  const FeetPose after{{10, -50, -kPi + 0.05f}, {0, 50, facing}};
  FootMotion left, right;
  feet_motion(before, after, left, right);
  EXPECT_NEAR(left.dtheta_rad, 0.1f, 1e-5f);
  EXPECT_NEAR(left.dx_mm, -10 * std::cos(0.05f), 1e-3f);
  EXPECT_NEAR(left.dy_mm, -10 * std::sin(0.05f), 1e-3f);
  EXPECT_EQ(right.dx_mm, 0);
  EXPECT_EQ(right.dtheta_rad, 0);
}

TEST(WalkCycleFeetMotion, ReplayingTheMotionsReproducesTheWalk) {
  // What the world does with feet_motion: apply each tick's motions in the body frame of
  // the feet before the tick. Done for 20 s of walking it must track the walk's feet.
  WalkCycle walk;
  FeetPose replay = walk.feet();
  for (int i = 0; i < 20 * kTicksPerSecond; ++i) {
    const FeetPose before = walk.feet();
    walk.tick(i < 15 * kTicksPerSecond ? WalkRequest{220, -90, 0.7f} : WalkRequest{}, kDt);
    FootMotion left, right;
    feet_motion(before, walk.feet(), left, right);
    const float heading = expected_body(replay).theta_rad;
    const float c = std::cos(heading), s = std::sin(heading);
    auto apply = [&](Pose2D& foot, const FootMotion& m) {
      foot.x_mm += c * m.dx_mm - s * m.dy_mm;
      foot.y_mm += s * m.dx_mm + c * m.dy_mm;
      foot.theta_rad = normalise_angle(foot.theta_rad + m.dtheta_rad);
    };
    apply(replay.left, left);
    apply(replay.right, right);
  }
  ASSERT_TRUE(walk.standing());
  expect_near_pose(replay.left, walk.feet().left, 0.5f, "left");
  expect_near_pose(replay.right, walk.feet().right, 0.5f, "right");
}

} // namespace
} // namespace touchline::robot
