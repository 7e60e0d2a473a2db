#include "touchline/sim/roster.hpp"

#include <gtest/gtest.h>

using touchline::sim::Roster;

TEST(Roster, FirstClaimantWinsAndASecondIsRefusedWithTheReason) {
  Roster roster(4);
  EXPECT_TRUE(roster.join({0, 2}, 111, 10).accepted);
  const auto second = roster.join({0, 2}, 222, 20);
  EXPECT_FALSE(second.accepted);
  EXPECT_NE(second.reason.find("team 0 player 2 is already played"), std::string::npos) << second.reason;
  EXPECT_NE(second.reason.find("pid 10"), std::string::npos) << second.reason;
  EXPECT_EQ(roster.find({0, 2})->instance, 111);
}

TEST(Roster, RepeatedJoinOfTheSameInstanceIsAccepted) {
  Roster roster(4);
  EXPECT_TRUE(roster.join({1, 1}, 5, 1).accepted);
  EXPECT_TRUE(roster.join({1, 1}, 5, 1).accepted);
  EXPECT_EQ(roster.members().size(), 1u);
}

TEST(Roster, PlayerOutsideTheTeamSizeIsRefused) {
  Roster roster(3);
  const auto reply = roster.join({0, 4}, 1, 1);
  EXPECT_FALSE(reply.accepted);
  EXPECT_EQ(reply.reason, "player 4 is not in a team of 3 (players 1..3)");
  EXPECT_FALSE(roster.join({0, 0}, 1, 1).accepted);
  EXPECT_FALSE(roster.join({2, 1}, 1, 1).accepted);
  EXPECT_TRUE(roster.members().empty());
}

TEST(Roster, NewInstanceTakesOverARobotThatTimedOut) {
  Roster roster(4);
  roster.join({0, 1}, 1, 100);
  roster.find({0, 1})->active = false;
  EXPECT_TRUE(roster.join({0, 1}, 2, 200).accepted);
  EXPECT_EQ(roster.find({0, 1})->instance, 2);
  EXPECT_EQ(roster.find({0, 1})->pid, 200);
}
