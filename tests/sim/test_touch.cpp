#include "touchline/sim/touch.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "touchline/angles.hpp"

using namespace touchline;

namespace {

/// The touch a robot at the origin facing +x feels from one robot 250 mm away at `bearing_deg`.
Touch touched_from(float bearing_deg) {
  Touch t;
  const float b = deg2rad(bearing_deg);
  sim::touch_update({}, {0, 0, 0}, 250 * std::cos(b), 250 * std::sin(b), t);
  return t;
}

int sectors(const Touch& t) { return t.front_left + t.front_right + t.left + t.right + t.back; }

} // namespace

// A robot feels a touch on the side it comes from: the foot bumpers ahead, the arms beside and behind.
TEST(Touch, ARobotWithinReachTouchesTheSectorOfItsBearing) {
  EXPECT_TRUE(touched_from(20).front_left);
  EXPECT_TRUE(touched_from(-20).front_right);
  EXPECT_TRUE(touched_from(90).left);
  EXPECT_TRUE(touched_from(-100).right);
  EXPECT_TRUE(touched_from(180).back);
  EXPECT_TRUE(touched_from(-150).back);
  for (float b : {20.f, -20.f, 90.f, -100.f, 180.f, -150.f}) EXPECT_EQ(sectors(touched_from(b)), 1) << b;
}

TEST(Touch, ARobotOutOfReachTouchesNothing) {
  Touch t;
  sim::touch_update({}, {0, 0, 0}, 300, 0, t); // at the 300 mm default: not nearer
  sim::touch_update({}, {0, 0, 0}, 0, -450, t);
  EXPECT_FALSE(t.any());
  sim::TouchDef off;
  off.distance_mm = 0;
  sim::touch_update(off, {0, 0, 0}, 100, 0, t);
  EXPECT_FALSE(t.any()) << "distance_mm 0: no robot feels a touch";
}

TEST(Touch, WorksInTheRobotFrameAndGathersEveryToucher) {
  // Robot at (1000, 1000) facing +y: (800, 1000) is on its left, (1000, 800) behind it.
  Touch t;
  sim::touch_update({}, {1000, 1000, kPi / 2}, 800, 1000, t);
  sim::touch_update({}, {1000, 1000, kPi / 2}, 1000, 800, t);
  EXPECT_TRUE(t.left);
  EXPECT_TRUE(t.back);
  EXPECT_EQ(sectors(t), 2);
}

TEST(Touch, AGoalPostIsFeltWithinItsOwnReach) {
  Touch t;
  sim::touch_post_update({}, {0, 0, 0}, 0, 190, t); // a post 190 mm to the left: within the 200 mm default
  EXPECT_TRUE(t.left);
  EXPECT_EQ(sectors(t), 1);
  Touch far;
  sim::touch_post_update({}, {0, 0, 0}, 250, 0, far); // where a robot would touch, a post does not
  EXPECT_FALSE(far.any());
  sim::touch_update({}, {0, 0, 0}, 250, 0, far);
  EXPECT_TRUE(far.front_left);
}
