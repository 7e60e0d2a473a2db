#include "touchline/behaviour/registry.hpp"

#include <gtest/gtest.h>

#include "skills/policy_files.hpp"

using touchline::behaviour::BehaviourError;
using touchline::behaviour::make_behaviour;

TEST(Registry, MakesEveryListedBehaviour) {
  const touchline::behaviour::test::TestDataDir data; // LearnedGoToPose reads its policy
  for (const auto& [name, help] : touchline::behaviour::behaviour_help()) {
    EXPECT_NE(make_behaviour(name, {}), nullptr) << name;
    EXPECT_FALSE(help.empty()) << name;
  }
}

TEST(Registry, WalkUsesItsParameters) {
  auto walk = make_behaviour("walk", {{"forward", "120"}, {"turn", "-0.5"}});
  const auto all = walk->tick(touchline::api::Blackboard{});
  EXPECT_FLOAT_EQ(all.body.forward, 120.f);
  EXPECT_FLOAT_EQ(all.body.turn, -0.5f);
}

TEST(Registry, UnknownNameListsTheKnownOnes) {
  try {
    make_behaviour("striker9000", {});
    FAIL();
  } catch (const BehaviourError& e) {
    EXPECT_EQ(std::string(e.what()), "unknown behaviour 'striker9000' (known: stand, walk, goto, GoToPose, LearnedGoToPose, GoToBall, LineUpAndKick, TrackBall, HeadScan, Team, Goalie, Striker, Midfielder, Defender)");
  }
}

TEST(Registry, BadParametersAreRejected) {
  EXPECT_THROW(make_behaviour("goto", {{"x", "12abc"}}), BehaviourError);
  EXPECT_THROW(make_behaviour("goto", {{"z", "1"}}), BehaviourError);
  EXPECT_THROW(make_behaviour("walk", {{"forward", ""}}), BehaviourError);
  EXPECT_THROW(make_behaviour("walk", {{"forward", "nan"}}), BehaviourError);
}
