#include "touchline/robot/dive_generator.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "touchline/robot/gait_feet.hpp"

using namespace touchline;
using namespace touchline::robot;
using api::ActionCommand::ActionType;

namespace {

/// The world's plausibility limit (sim kMaxFootTravelPerTickMm): the robot library may not
/// include the world, so the figure is repeated here.
constexpr float kWorldFootLimitMm = 100.f;

api::ActionCommand::Body dive(ActionType side) {
  api::ActionCommand::Body b;
  b.actionType = side;
  return b;
}

float travel(const FootMotion& m) { return std::hypot(m.dx_mm, m.dy_mm); }

struct DiveRun {
  Pose2D start, end;             ///< body pose before the dive and after it is over
  FeetPose start_feet, end_feet;
  float max_foot_step_mm = 0;    ///< largest per-tick foot travel
  int ticks = 0;                 ///< ticks the dive ran
};

/// A standing robot at `start` dives to `side`.
DiveRun dive_from(const Pose2D& start, ActionType side) {
  WalkCycle walk;
  walk.stand_at(start);
  DiveGenerator generator;
  DiveRun run;
  run.start = walk.odometry();
  run.start_feet = walk.feet();
  FeetPose before = run.start_feet;
  generator.start(dive(side));
  for (; generator.running() && run.ticks < 1000; ++run.ticks) {
    const FeetPose now = generator.tick(walk);
    FootMotion l, r;
    feet_motion(before, now, l, r);
    run.max_foot_step_mm = std::max({run.max_foot_step_mm, travel(l), travel(r)});
    before = now;
  }
  run.end = walk.odometry();
  run.end_feet = walk.feet();
  return run;
}

/// `v` turned into the frame of heading `theta`: (forward, left).
std::pair<float, float> in_body(float dx, float dy, float theta) {
  return {std::cos(theta) * dx + std::sin(theta) * dy, -std::sin(theta) * dx + std::cos(theta) * dy};
}

} // namespace

TEST(DiveGenerator, TheDefaultsAreABodyLengthInRunswiftsTimes) {
  const DiveDef def;
  EXPECT_FLOAT_EQ(def.reach_mm, 500.f);
  EXPECT_FLOAT_EQ(def.fall_s, 0.4f);
  EXPECT_FLOAT_EQ(def.duration_s, 2.4f);
  const DiveGenerator g;
  EXPECT_EQ(g.fall_ticks(), 40);
  EXPECT_EQ(g.total_ticks(), 240);
}

TEST(DiveGenerator, TheBodyAndBothFeetLandAReachToTheDivesSideWhateverTheHeading) {
  const float reach = DiveDef{}.reach_mm;
  for (float heading : {0.f, 0.7f, 2.5f, -2.0f, 3.1f}) {
    for (ActionType side : {ActionType::GOALIE_DIVE_LEFT, ActionType::GOALIE_DIVE_RIGHT}) {
      const DiveRun run = dive_from({1200.f, -800.f, heading}, side);
      const float want_left = side == ActionType::GOALIE_DIVE_LEFT ? reach : -reach;
      const auto [fwd, left] = in_body(run.end.x_mm - run.start.x_mm, run.end.y_mm - run.start.y_mm, heading);
      EXPECT_NEAR(fwd, 0.f, 0.5f) << heading;
      EXPECT_NEAR(left, want_left, 0.5f) << heading;
      EXPECT_NEAR(run.end.theta_rad, run.start.theta_rad, 1e-4f) << heading;
      EXPECT_EQ(run.ticks, 240) << heading;
      for (const auto& [was, now] : {std::pair{run.start_feet.left, run.end_feet.left},
                                     std::pair{run.start_feet.right, run.end_feet.right}}) {
        const auto [f, l] = in_body(now.x_mm - was.x_mm, now.y_mm - was.y_mm, heading);
        EXPECT_NEAR(f, 0.f, 0.5f) << heading;
        EXPECT_NEAR(l, want_left, 0.5f) << heading;
      }
    }
  }
}

TEST(DiveGenerator, NoTickMovesAFootFurtherThanTheWorldAllows) {
  const DiveRun run = dive_from({0, 0, 0.4f}, ActionType::GOALIE_DIVE_RIGHT);
  EXPECT_GT(run.max_foot_step_mm, 10.f); // it does move, fast: pi * 500 / 80 = 19.6 mm a tick at the peak
  EXPECT_LT(run.max_foot_step_mm, kWorldFootLimitMm);
}

TEST(DiveGenerator, TheRobotStaysDownForTheWholeDurationThenWalksFromWhereItLanded) {
  GaitFeet gait(WalkDef{}, KickDef{});
  gait.tick(dive(ActionType::GOALIE_DIVE_LEFT), 0.01f);
  const int total = gait.dive().total_ticks();
  FeetPose landed;
  for (int tick = 2; tick <= total; ++tick) {
    gait.tick(api::ActionCommand::walk(300, 100, 0.5f), 0.01f); // ignored while down
    EXPECT_EQ(gait.status().active.actionType, ActionType::GOALIE_DIVE_LEFT) << tick;
    EXPECT_FALSE(gait.status().standing) << tick;
    if (tick == gait.dive().fall_ticks()) landed = gait.feet();
    if (tick > gait.dive().fall_ticks()) { // lying: not a foot moves
      EXPECT_EQ(gait.feet().left.x_mm, landed.left.x_mm) << tick;
      EXPECT_EQ(gait.feet().left.y_mm, landed.left.y_mm) << tick;
      EXPECT_EQ(gait.feet().right.x_mm, landed.right.x_mm) << tick;
      EXPECT_EQ(gait.feet().right.y_mm, landed.right.y_mm) << tick;
    }
  }
  EXPECT_FALSE(gait.dive().running()); // 2.4 s: over
  EXPECT_NEAR(gait.odometry().y_mm, DiveDef{}.reach_mm, 0.5f);
  // Up again: the walk goes on from the landing.
  for (int tick = 0; tick < 100; ++tick) gait.tick(api::ActionCommand::walk(300, 0, 0), 0.01f);
  EXPECT_EQ(gait.status().active.actionType, ActionType::WALK);
  EXPECT_FALSE(gait.status().standing);
  EXPECT_GT(gait.odometry().x_mm, 50.f);
  EXPECT_NEAR(gait.odometry().y_mm, DiveDef{}.reach_mm, 5.f);
}

TEST(DiveGenerator, ADiveFromAWalkStillLandsSquareAReachBesideWhereItStarted) {
  GaitFeet gait(WalkDef{}, KickDef{});
  for (int tick = 0; tick < 137; ++tick) gait.tick(api::ActionCommand::walk(300, 0, 0), 0.01f); // mid-step
  ASSERT_FALSE(gait.walk().standing());
  const Pose2D start = gait.odometry();
  FeetPose before = gait.feet();
  float max_step = 0;
  gait.tick(dive(ActionType::GOALIE_DIVE_RIGHT), 0.01f);
  while (gait.dive().running()) {
    FootMotion l, r;
    feet_motion(before, gait.feet(), l, r);
    max_step = std::max({max_step, travel(l), travel(r)});
    before = gait.feet();
    gait.tick(api::ActionCommand::walk(300, 0, 0), 0.01f);
  }
  EXPECT_LT(max_step, kWorldFootLimitMm);
  const auto [fwd, left] = in_body(gait.odometry().x_mm - start.x_mm, gait.odometry().y_mm - start.y_mm, start.theta_rad);
  EXPECT_NEAR(fwd, 0.f, 1.f);
  EXPECT_NEAR(left, -DiveDef{}.reach_mm, 1.f);
  EXPECT_TRUE(gait.walk().standing()); // the walk stood up square where the robot landed
}

TEST(DiveGenerator, OtherActionsDoNotStartIt) {
  DiveGenerator g;
  g.start(api::ActionCommand::walk(100, 0, 0));
  EXPECT_FALSE(g.running());
  api::ActionCommand::Body kick;
  kick.actionType = ActionType::KICK;
  g.start(kick);
  EXPECT_FALSE(g.running());
  g.start(dive(ActionType::GOALIE_DIVE_RIGHT));
  EXPECT_TRUE(g.running());
}
