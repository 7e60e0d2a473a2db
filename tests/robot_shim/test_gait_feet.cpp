#include "touchline/robot/gait_feet.hpp"

#include <gtest/gtest.h>

#include <utility>

using namespace touchline;
using namespace touchline::robot;

TEST(GaitFeet, AWalkRequestIsScaledBySpeedAndAnythingElseAsksForNothing) {
  api::ActionCommand::Body body = api::ActionCommand::walk(200, -100, 0.5f);
  body.speed = 0.5f;
  const WalkRequest r = walk_request(body);
  EXPECT_FLOAT_EQ(r.forward_mm_s, 100);
  EXPECT_FLOAT_EQ(r.left_mm_s, -50);
  EXPECT_FLOAT_EQ(r.turn_rad_s, 0.25f);
  body.actionType = api::ActionCommand::ActionType::GETUP_FRONT;
  EXPECT_EQ(walk_request(body).forward_mm_s, 0.f);
}

TEST(GaitFeet, AKickLatchesUntilItCompletesWhateverIsAskedMeanwhile) {
  GaitFeet gait(WalkDef{}, KickDef{});
  api::ActionCommand::Body kick;
  kick.actionType = api::ActionCommand::ActionType::KICK;
  gait.tick(kick, 0.01f);
  EXPECT_EQ(gait.status().kick_phase, static_cast<int>(KickPhase::kPrepare));
  int ticks = 1;
  for (; gait.kick().running() && ticks < 1000; ++ticks) {
    gait.tick(api::ActionCommand::walk(300, 0, 0), 0.01f); // ignored until the kick is done
    EXPECT_EQ(gait.status().active.actionType, api::ActionCommand::ActionType::KICK);
  }
  EXPECT_LT(ticks, 1000);
  EXPECT_TRUE(gait.walk().standing());
  gait.tick(api::ActionCommand::walk(300, 0, 0), 0.01f);
  EXPECT_EQ(gait.status().active.actionType, api::ActionCommand::ActionType::WALK);
  EXPECT_FALSE(gait.status().standing);
}

// The referee put the robot down mid-kick: the kick stops, the walk stands with its feet
// square around where the body was.
TEST(GaitFeet, PlacedStopsAKickAndStandsSquare) {
  GaitFeet gait(WalkDef{}, KickDef{});
  for (int t = 0; t < 30; ++t) gait.tick(api::ActionCommand::walk(200, 0, 0.3f), 0.01f);
  api::ActionCommand::Body kick;
  kick.actionType = api::ActionCommand::ActionType::KICK;
  for (int t = 0; t < 60; ++t) gait.tick(kick, 0.01f);
  ASSERT_TRUE(gait.kick().running());
  const Pose2D body = gait.odometry();
  gait.placed();
  EXPECT_FALSE(gait.kick().running());
  EXPECT_TRUE(gait.walk().standing());
  EXPECT_EQ(gait.status().kick_phase, 0);
  const FeetPose rest = gait.walk().feet_at_rest(body);
  for (const auto& [foot, at] : {std::pair{gait.feet().left, rest.left}, std::pair{gait.feet().right, rest.right}}) {
    EXPECT_NEAR(foot.x_mm, at.x_mm, 1e-3f);
    EXPECT_NEAR(foot.y_mm, at.y_mm, 1e-3f);
    EXPECT_NEAR(foot.theta_rad, at.theta_rad, 1e-5f);
  }
}
