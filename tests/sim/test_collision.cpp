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

TEST(Collision, StepsTowardsTellsAStepIntoTheOtherFromOneAwayOrAside) {
  const Pose2D loser{0, 0, kPi / 2}, winner{0, 250, -kPi / 2}; // facing each other along +y
  const auto tick = [](float dx_mm, float dy_mm) {
    TickMotion m;
    m.left = m.right = {dx_mm, dy_mm, 0};
    return m;
  };
  EXPECT_TRUE(sim::steps_towards(loser, tick(5, 0), winner));   // forward: into it
  EXPECT_FALSE(sim::steps_towards(loser, tick(-5, 0), winner)); // backwards: away
  EXPECT_FALSE(sim::steps_towards(loser, tick(0, 5), winner));  // sideways: square to it
  EXPECT_FALSE(sim::steps_towards(loser, tick(0, 0), winner));  // standing or turning
  TickMotion kick; // one foot swinging forward moves the body forward: into it
  kick.right = {12, 0, 0};
  EXPECT_TRUE(sim::steps_towards(loser, kick, winner));
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

// --- walking into (rules.pushing_model = walking_into) ----------------------------------

TEST(Collision, SpeedTowardsIsTheVelocityAlongTheLineToTheOther) {
  const Pose2D a{0, 0, 0}, b{200, 0, kPi};
  EXPECT_FLOAT_EQ(sim::speed_towards(a, {150, 0}, b), 150);   // straight at b
  EXPECT_FLOAT_EQ(sim::speed_towards(a, {-80, 0}, b), -80);   // backing away
  EXPECT_FLOAT_EQ(sim::speed_towards(a, {0, 300}, b), 0);     // passing square to it
  EXPECT_FLOAT_EQ(sim::speed_towards(a, {100, 100}, b), 100); // the component towards it
  EXPECT_FLOAT_EQ(sim::speed_towards(a, {100, 0}, a), 0);     // no line to walk along
}

namespace {
// Both facing +x far from the ball: the thesis names b (behind, at x = 0) the pusher.
const Pose2D kAhead{200, 0, 0}, kBehind{0, 0, 0};
const sim::CollisionVerdict kBehindPushes = sim::judge_collision({}, kAhead, kBehind, 3000, 2000);
constexpr float kWalkingIntoMmS = 50;
} // namespace

TEST(Collision, TheThesisPusherWalkingInPushes) {
  ASSERT_EQ(kBehindPushes.pusher, 1);
  EXPECT_EQ(sim::walking_pusher(kBehindPushes, kAhead, {}, kBehind, {120, 0}, kWalkingIntoMmS), 1);
  // Both walking in: the thesis still decides.
  EXPECT_EQ(sim::walking_pusher(kBehindPushes, kAhead, {-120, 0}, kBehind, {120, 0}, kWalkingIntoMmS), 1);
}

TEST(Collision, AStandingRobotWalkedIntoDoesNotPushTheWalkerDoes) {
  // The robot ahead backs into the one behind, which stands: the thesis would call the stander.
  EXPECT_EQ(sim::walking_pusher(kBehindPushes, kAhead, {-120, 0}, kBehind, {}, kWalkingIntoMmS), 0);
}

TEST(Collision, NeitherWalkingInIsNoFoul) {
  EXPECT_EQ(sim::walking_pusher(kBehindPushes, kAhead, {}, kBehind, {}, kWalkingIntoMmS), -1);
  // Slower than the threshold, backing away, or passing square: not walking into it.
  EXPECT_EQ(sim::walking_pusher(kBehindPushes, kAhead, {40, 0}, kBehind, {40, 0}, kWalkingIntoMmS), -1);
  EXPECT_EQ(sim::walking_pusher(kBehindPushes, kAhead, {0, 250}, kBehind, {-100, 0}, kWalkingIntoMmS), -1);
}

TEST(Collision, OnlyAPushingVerdictHasAWalkingPusher) {
  const auto contest = sim::judge_collision({}, {0, 0, 0}, {250, 0, kPi}, 150, 0);
  EXPECT_EQ(sim::walking_pusher(contest, {0, 0, 0}, {200, 0}, {250, 0, kPi}, {}, kWalkingIntoMmS), -1);
}
