#include "touchline/robot/walk_cycle_engine.hpp"

#include <gtest/gtest.h>

using namespace touchline;
using namespace touchline::robot;

TEST(WalkCycleEngine, ItIsTheWalkCycleEvery10MsBitForBit) {
  WalkCycleEngine engine(WalkDef{}, KickDef{});
  EXPECT_EQ(engine.period_us(), 10000);
  EXPECT_EQ(engine.output_kind(), EngineOutputKind::kFeet);
  WalkCycle walk{WalkDef{}};
  WalkEngineOutput out;
  engine.start(out);
  EXPECT_EQ(out.feet.left.y_mm, walk.feet().left.y_mm);
  for (int i = 0; i < 300; ++i) {
    const auto body = api::ActionCommand::walk(250, 40, i < 150 ? 0.7f : -0.3f);
    engine.tick(body, nao::Sensors{}, out);
    walk.tick(walk_request(body), 0.01f);
    ASSERT_EQ(out.feet.left.x_mm, walk.feet().left.x_mm) << i;
    ASSERT_EQ(out.feet.right.y_mm, walk.feet().right.y_mm) << i;
    ASSERT_EQ(out.feet.right.theta_rad, walk.feet().right.theta_rad) << i;
    ASSERT_EQ(out.odometry.x_mm, walk.odometry().x_mm) << i;
  }
  EXPECT_NE(engine.gait(), nullptr);
}
