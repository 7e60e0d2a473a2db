#include "touchline/sim/collision.hpp"

#include <gtest/gtest.h>

#include "touchline/angles.hpp"

using namespace touchline;
using sim::Collision;

TEST(Collision, Algorithm21TellsSameWayFromFacingEachOther) {
  EXPECT_TRUE(sim::facing_same_way(0.1f, 0.5f));
  EXPECT_FALSE(sim::facing_same_way(0.f, kPi));
  EXPECT_FALSE(sim::facing_same_way(0.f, deg2rad(95)));
  EXPECT_TRUE(sim::facing_same_way(0.f, deg2rad(85)));
  // The thesis's [0, 2pi) subtraction would call these "facing each other".
  EXPECT_TRUE(sim::facing_same_way(deg2rad(5), deg2rad(-5)));
}

TEST(Collision, Algorithm22FindsWhoIsInFront) {
  const Pose2D behind{0, 0, 0}, ahead{200, 30, 0.2f};
  EXPECT_TRUE(sim::in_front_of(ahead, behind));
  EXPECT_FALSE(sim::in_front_of(behind, ahead));
}

TEST(Collision, FarApartIsNoCollision) {
  EXPECT_EQ(sim::judge_collision({}, {0, 0, 0}, {400, 0, kPi}, 200, 0).kind, Collision::kNone);
}

TEST(Collision, ContestingTheBallTheNearerGoesOnTheOtherIsStopped) {
  // Facing each other over a ball nearer to b.
  const auto v = sim::judge_collision({}, {0, 0, 0}, {250, 0, kPi}, 150, 0);
  EXPECT_EQ(v.kind, Collision::kContesting);
  EXPECT_FALSE(v.same_way);
  EXPECT_EQ(v.stopped, 0);
}

TEST(Collision, SameWayAwayFromTheBallTheRobotBehindIsPenalised) {
  const auto v = sim::judge_collision({}, {1000, 0, 0}, {800, 50, 0.1f}, -2000, 0);
  EXPECT_EQ(v.kind, Collision::kPushing);
  EXPECT_TRUE(v.same_way);
  EXPECT_EQ(v.pusher, 1); // b is behind a
}

TEST(Collision, FacingEachOtherAwayFromTheBallTheSquarerWalkerPushes) {
  // a walks straight at b; b is turned 60 degrees away from a.
  const auto v = sim::judge_collision({}, {0, 0, 0}, {250, 0, kPi - deg2rad(60)}, 3000, 2000);
  EXPECT_EQ(v.kind, Collision::kPushing);
  EXPECT_FALSE(v.same_way);
  EXPECT_EQ(v.pusher, 0);
}
