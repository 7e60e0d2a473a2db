#include "touchline/behaviour/walk_skills.hpp"

#include <gtest/gtest.h>

using namespace touchline::api;
using touchline::behaviour::ConstantWalk;

TEST(ConstantWalk, AsksForItsVelocityWhateverTheBlackboardSays) {
  ConstantWalk walk(200.f, -50.f, 0.3f);
  Blackboard blackboard;
  for (float x : {0.f, 1000.f}) {
    blackboard.localisation.robotPos = {x, 0.f, 1.f};
    const ActionCommand::All all = walk.tick(blackboard);
    EXPECT_EQ(all.body.actionType, ActionCommand::ActionType::WALK);
    EXPECT_FLOAT_EQ(all.body.forward, 200.f);
    EXPECT_FLOAT_EQ(all.body.left, -50.f);
    EXPECT_FLOAT_EQ(all.body.turn, 0.3f);
  }
}
