#include "touchline/sim/lockstep.hpp"

#include <gtest/gtest.h>

#include <vector>

using touchline::RobotId;
using touchline::sim::FrameBarrier;

TEST(FrameBarrier, CompleteOnlyWhenEveryExpectedRobotAnswered) {
  FrameBarrier barrier;
  barrier.begin(7, {{0, 1}, {1, 2}}, /*now_us=*/0, /*timeout_us=*/1000);
  EXPECT_FALSE(barrier.complete(10));
  EXPECT_TRUE(barrier.answer({0, 1}, 7));
  EXPECT_FALSE(barrier.complete(10));
  EXPECT_TRUE(barrier.answer({1, 2}, 7));
  EXPECT_TRUE(barrier.complete(10));
  EXPECT_TRUE(barrier.missing().empty());
}

TEST(FrameBarrier, AnswersForOtherFramesDoNotCount) {
  FrameBarrier barrier;
  barrier.begin(7, {{0, 1}}, 0, 1000);
  EXPECT_FALSE(barrier.answer({0, 1}, 6));
  EXPECT_FALSE(barrier.answer({0, 1}, 8));
  EXPECT_FALSE(barrier.complete(10));
  ASSERT_EQ(barrier.missing().size(), 1u);
}

TEST(FrameBarrier, DeadlineEndsTheWaitAndNamesTheLateRobots) {
  FrameBarrier barrier;
  barrier.begin(3, {{0, 1}, {0, 2}, {1, 1}}, 5000, 1000);
  barrier.answer({0, 2}, 3);
  EXPECT_FALSE(barrier.complete(5999));
  EXPECT_EQ(barrier.remaining_us(5500), 500);
  EXPECT_TRUE(barrier.complete(6000));
  EXPECT_EQ(barrier.remaining_us(7000), 0);
  const auto missing = barrier.missing();
  ASSERT_EQ(missing.size(), 2u);
  EXPECT_EQ(missing[0], (RobotId{0, 1}));
  EXPECT_EQ(missing[1], (RobotId{1, 1}));
}

TEST(FrameBarrier, NoExpectedRobotsIsCompleteAtOnce) {
  FrameBarrier barrier;
  barrier.begin(0, {}, 0, 1000);
  EXPECT_TRUE(barrier.complete(0));
}

TEST(FrameBarrier, UnexpectedRobotDoesNotDisturbTheWait) {
  FrameBarrier barrier;
  barrier.begin(1, {{0, 1}}, 0, 1000);
  EXPECT_TRUE(barrier.answer({1, 4}, 1)); // e.g. a rejoining robot
  EXPECT_FALSE(barrier.complete(1));
}

TEST(FrameBarrier, PastTheDeadlineItWaitsLongerForTheRobotsItDoesNotGiveUp) {
  FrameBarrier barrier;
  barrier.begin(4, {{0, 1}, {1, 1}}, 0, 1000);
  ASSERT_TRUE(barrier.complete(1000));
  barrier.give_up({0, 1}); // its process is gone
  barrier.wait_until(5000); // the other's still runs
  EXPECT_FALSE(barrier.complete(1000));
  EXPECT_EQ(barrier.remaining_us(1000), 4000);
  EXPECT_EQ(barrier.missing(), (std::vector<RobotId>{{1, 1}}));
  EXPECT_TRUE(barrier.answer({1, 1}, 4));
  EXPECT_TRUE(barrier.complete(1000));
  EXPECT_TRUE(barrier.missing().empty());
}
