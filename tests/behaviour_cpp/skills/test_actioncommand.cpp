// actioncommand: the request builders (same defaults as behaviour_py/actioncommand.py).
#include "touchline/behaviour/skills/actioncommand.hpp"

#include <gtest/gtest.h>

namespace actioncommand = touchline::behaviour::actioncommand;
using namespace touchline::api::ActionCommand;

TEST(ActionCommand, WalkSetsVelocitiesAndSpeed) {
  const Body body = actioncommand::walk(120.f, -30.f, 0.5f, 0.5f);
  EXPECT_EQ(body.actionType, ActionType::WALK);
  EXPECT_EQ(body.forward, 120.f);
  EXPECT_EQ(body.left, -30.f);
  EXPECT_EQ(body.turn, 0.5f);
  EXPECT_EQ(body.speed, 0.5f);
}

TEST(ActionCommand, StandIsTheBodyDefault) {
  const Body body = actioncommand::stand();
  EXPECT_EQ(body.actionType, ActionType::STAND);
  EXPECT_EQ(body.forward, 0.f);
  EXPECT_EQ(body.left, 0.f);
  EXPECT_EQ(body.turn, 0.f);
}

TEST(ActionCommand, KickAndDribbleDefaults) {
  const Body kick = actioncommand::kick();
  EXPECT_EQ(kick.actionType, ActionType::KICK);
  EXPECT_EQ(kick.power, 1.f);
  EXPECT_EQ(kick.foot, Foot::LEFT);
  EXPECT_EQ(kick.bend, 0.f);
  const Body dribble = actioncommand::dribble(0.3f, Foot::RIGHT);
  EXPECT_EQ(dribble.actionType, ActionType::DRIBBLE);
  EXPECT_FLOAT_EQ(dribble.power, 0.3f);
  EXPECT_EQ(dribble.foot, Foot::RIGHT);
}

TEST(ActionCommand, HeadAndLeds) {
  const Head head = actioncommand::head(0.5f, -0.25f, true, 0.5f);
  EXPECT_EQ(head.yaw, 0.5f);
  EXPECT_EQ(head.pitch, -0.25f);
  EXPECT_TRUE(head.isRelative);
  EXPECT_EQ(head.yawSpeed, 0.5f);
  EXPECT_EQ(head.pitchSpeed, 1.f);
  EXPECT_EQ(actioncommand::leds().chest, 0x00ff00);
  EXPECT_EQ(actioncommand::leds(0xff0000).chest, 0xff0000);
}

TEST(ActionCommand, ComposeKeepsDefaultsForMissingParts) {
  All command = actioncommand::compose({}, actioncommand::walk(100.f));
  EXPECT_EQ(command.body.forward, 100.f);
  EXPECT_EQ(command.head.yaw, 0.f);
  EXPECT_EQ(command.head.pitch, 0.f);
  EXPECT_EQ(command.leds.chest, 0x00ff00);
  command = actioncommand::compose(actioncommand::head(1.f), {}, actioncommand::leds(0x0000ff));
  EXPECT_EQ(command.body.actionType, ActionType::STAND);
  EXPECT_EQ(command.head.yaw, 1.f);
  EXPECT_EQ(command.leds.chest, 0x0000ff);
}
