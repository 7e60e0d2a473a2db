// JointFeet: the world's feet from leg joints. Driven by our joint walk (NaoJointWalk), whose
// planned feet are known, so what the projection does can be checked against the plan.
#include "touchline/robot/nao/joint_feet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "touchline/angles.hpp"
#include "touchline/robot/nao_joint_walk.hpp"

using namespace touchline;
using namespace touchline::robot;
using nao::Side;

namespace {

struct Walker {
  NaoJointWalk walk{NaoJointWalkDef{}, WalkDef{}, KickDef{}};
  nao::JointFeet feet;
  WalkEngineOutput out;
  Walker() {
    walk.start(out);
    feet.reset(out.joints);
  }
  const FeetPose& tick(const api::ActionCommand::Body& body) {
    walk.tick(body, nao::Sensors{}, out);
    return feet.update(out.joints);
  }
};

const Pose2D& foot(const FeetPose& feet, Side side) { return side == Side::kLeft ? feet.left : feet.right; }

} // namespace

TEST(JointFeet, StandingTheFeetAreSideBySideAroundTheOrigin) {
  Walker w;
  EXPECT_NEAR(w.feet.feet().left.x_mm, 0.f, 1e-3f);
  EXPECT_NEAR(w.feet.feet().left.y_mm, 50.f, 1e-3f);
  EXPECT_NEAR(w.feet.feet().right.y_mm, -50.f, 1e-3f);
  EXPECT_NEAR(w.feet.feet().left.theta_rad, 0.f, 1e-6f);
  for (int i = 0; i < 50; ++i) w.tick(api::ActionCommand::stand());
  EXPECT_NEAR(w.feet.feet().left.y_mm, 50.f, 1e-3f);
  EXPECT_NEAR(w.feet.feet().right.x_mm, 0.f, 1e-3f);
}

TEST(JointFeet, TheStanceFootDoesNotSlideWhileTheOtherSwings) {
  Walker w;
  int swinging_ticks = 0;
  for (int i = 0; i < 600; ++i) {
    const Side stance = w.feet.stance();
    const Pose2D before = foot(w.feet.feet(), stance);
    w.tick(api::ActionCommand::walk(250, 60, 0.6f));
    if (w.feet.stance_changed()) continue; // the weight just moved
    ASSERT_EQ(w.feet.stance(), stance);
    const Pose2D after = foot(w.feet.feet(), stance);
    EXPECT_EQ(after.x_mm, before.x_mm);
    EXPECT_EQ(after.y_mm, before.y_mm);
    EXPECT_EQ(after.theta_rad, before.theta_rad);
    if (w.feet.swing_height_mm() > w.feet.def().lift_mm) ++swinging_ticks;
  }
  EXPECT_GT(swinging_ticks, 300); // most of the time one foot is in the air
}

TEST(JointFeet, TheWeightMovesToTheSwingFootWhenItTouchesDown) {
  Walker w;
  int touchdowns = 0, lift_offs = 0;
  Side stance = w.feet.stance();
  for (int i = 0; i < 500; ++i) { // 5 s at 10 ms
    const bool left_was_swinging = w.walk.gait()->walk().left_swinging();
    const float lift_before = w.walk.swing_lift_mm();
    w.tick(api::ActionCommand::walk(200, 0, 0));
    if (w.feet.stance_changed() && !w.feet.touched_down()) {
      ++lift_offs; // the sole bearing the weight rose: the other bears it
      EXPECT_NE(w.feet.stance(), stance);
      stance = w.feet.stance();
      continue;
    }
    if (!w.feet.touched_down()) {
      EXPECT_EQ(w.feet.stance(), stance);
      continue;
    }
    ++touchdowns;
    // It is the foot that was lifted, and it has just come down.
    EXPECT_EQ(w.feet.stance(), left_was_swinging ? Side::kLeft : Side::kRight);
    EXPECT_NE(w.feet.stance(), stance);
    EXPECT_GT(lift_before, 0.f);
    EXPECT_LT(w.walk.swing_lift_mm(), w.feet.def().touchdown_mm);
    stance = w.feet.stance();
  }
  // Standing, the left sole bore the weight; the walk's first step lifts it.
  EXPECT_EQ(lift_offs, 1);
  // Then one touchdown a step (0.25 s).
  EXPECT_GE(touchdowns, 19);
  EXPECT_LE(touchdowns, 20);
}

namespace {
/// The worst distance (mm) and heading difference (rad) between the projected and the
/// planned feet over `ticks` ticks of `body`.
std::pair<float, float> worst_difference(const api::ActionCommand::Body& body, int ticks) {
  Walker w;
  float worst_mm = 0, worst_rad = 0;
  for (int i = 0; i < ticks; ++i) {
    const FeetPose& got = w.tick(body);
    // The plan's frame and the projection's start at the same standing feet, so they agree
    // as long as the stance foot never slides and the swing foot lands where planned.
    const FeetPose& plan = w.walk.gait()->feet();
    for (Side side : {Side::kLeft, Side::kRight}) {
      worst_mm = std::max(worst_mm, std::hypot(foot(got, side).x_mm - foot(plan, side).x_mm,
                                               foot(got, side).y_mm - foot(plan, side).y_mm));
      worst_rad = std::max(worst_rad, std::abs(normalise_angle(foot(got, side).theta_rad - foot(plan, side).theta_rad)));
    }
  }
  return {worst_mm, worst_rad};
}
} // namespace

TEST(JointFeet, TheProjectedFeetFollowThePlannedFeet) {
  for (const auto& body : {api::ActionCommand::walk(300, 0, 0), api::ActionCommand::walk(0, -150, 0),
                           api::ActionCommand::walk(0, 0, 1.2f)}) {
    const auto [mm, rad] = worst_difference(body, 800);
    EXPECT_LT(mm, 0.1f);
    EXPECT_LT(rad, 1e-3f);
  }
}

TEST(JointFeet, WalkingAndTurningAtOnceTheSharedHipYawPitchCostsALittleHeading) {
  // One HipYawPitch for both legs cannot give feet at different x exactly mirrored yaws:
  // each step lands a fraction of a milliradian off, and the error adds up.
  const auto [mm, rad] = worst_difference(api::ActionCommand::walk(300, -50, -0.8f), 800);
  EXPECT_LT(rad, 0.008f); // 8 s: under 0.06 degrees a second
  EXPECT_LT(mm, 5.f);
}
