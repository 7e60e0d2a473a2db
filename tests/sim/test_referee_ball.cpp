// The ball leaving the field: put back on the line it crossed, 1 m (ball_out_setback_mm)
// towards the own goal of the team that touched it last. SPL 2011 field: half length
// 3000, half width 2000, goal half-width 700, posts 100 mm; ball radius 32.5 mm.
#include <gtest/gtest.h>

#include "referee_fixture.hpp"

namespace touchline::sim {
namespace {

class BallOut : public RefereeTest {
 protected:
  /// The ball at (x, y) with velocity (vx, vy) during PLAYING, last touched by `team`:
  /// where the referee puts it (fails if it does not).
  BallPlacement put_back(float x, float y, int team, float vx = 0, float vy = 0) {
    if (!referee) start_playing();
    put_ball(x, y, vx, vy);
    input.last_touch_team = team;
    now_s += 1;
    const auto d = update_at(now_s);
    EXPECT_TRUE(d.ball.has_value());
    return d.ball.value_or(BallPlacement{});
  }
  double now_s = kKickOffS;
};

void expect_ball(const BallPlacement& b, float x, float y) {
  EXPECT_EQ(b.why, BallPlacement::Why::kBallOut);
  EXPECT_NEAR(b.x_mm, x, 1e-3f);
  EXPECT_NEAR(b.y_mm, y, 1e-3f);
}

TEST_F(BallOut, OverATouchlineItGoesBackTowardsTheLastTouchersGoal) {
  expect_ball(put_back(500.f, 2040.f, 0), -500.f, 2000.f);  // team 0 defends -x
  expect_ball(put_back(500.f, 2040.f, 1), 1500.f, 2000.f);  // team 1 defends +x
  expect_ball(put_back(500.f, 2040.f, -1), 500.f, 2000.f);  // unknown: where it left
  expect_ball(put_back(-700.f, -2040.f, 1), 300.f, -2000.f); // the other touchline
  expect_ball(put_back(-700.f, -2040.f, 0), -1700.f, -2000.f);
}

TEST_F(BallOut, TheCrossingPointIsTracedBackAlongTheBallsPath) {
  // 100 mm past the touchline moving (1000, 1000) mm/s: it crossed 0.1 s ago at x = 500.
  expect_ball(put_back(600.f, 2100.f, -1, 1000.f, 1000.f), 500.f, 2000.f);
  // Bounced back off the wall (moving into the field): no way to trace, use x as it is.
  expect_ball(put_back(600.f, 2100.f, -1, 1000.f, -1000.f), 600.f, 2000.f);
}

TEST_F(BallOut, SetbackStopsAtTheCorner) {
  expect_ball(put_back(2800.f, 2040.f, 1), 3000.f, 2000.f);
  expect_ball(put_back(-2800.f, -2040.f, 0), -3000.f, -2000.f);
}

TEST_F(BallOut, OverAGoalLineByTheAttackersItGoesBackOneMetreIntoTheField) {
  expect_ball(put_back(3040.f, 1500.f, 0), 2000.f, 1500.f);
  expect_ball(put_back(-3040.f, -1200.f, 1), -2000.f, -1200.f);
}

TEST_F(BallOut, OverTheirOwnGoalLineByTheDefendersItStaysOnTheLine) {
  expect_ball(put_back(3040.f, 1500.f, 1), 3000.f, 1500.f);
  expect_ball(put_back(3040.f, 1500.f, -1), 3000.f, 1500.f);
  // Beside the post, it is moved clear of it: 700 + 50 + 32.5 from the centre line.
  expect_ball(put_back(3040.f, 760.f, -1), 3000.f, 782.5f);
  expect_ball(put_back(-3040.f, -720.f, 0), -3000.f, -782.5f);
}

TEST_F(BallOut, OverACornerTheLineCrossedFirstCounts) {
  // 50 mm past the goal line and 80 mm past the touchline. Moving (1000, 2000) mm/s it
  // crossed the goal line 0.05 s ago, the touchline 0.04 s ago: out over the goal line,
  // at y = 2080 - 0.05 * 2000 = 1980.
  expect_ball(put_back(3050.f, 2080.f, -1, 1000.f, 2000.f), 3000.f, 1980.f);
  // Moving (2000, 1000) mm/s: the touchline 0.08 s ago, first; at x = 3050 - 160 = 2890.
  expect_ball(put_back(3050.f, 2080.f, -1, 2000.f, 1000.f), 2890.f, 2000.f);
}

TEST_F(BallOut, InsetPutsItInsideTheLine) {
  rules.ball_out_inset_mm = 400;
  expect_ball(put_back(500.f, 2040.f, -1), 500.f, 1600.f);
  expect_ball(put_back(3040.f, 1500.f, 1), 2600.f, 1500.f);
}

TEST_F(RefereeTest, BallOnTheTouchlineIsStillIn) {
  start_playing();
  put_ball(500.f, 2032.5f); // its edge on the line's outer edge
  EXPECT_FALSE(update_at(60).ball.has_value());
}

TEST_F(RefereeTest, BallOutIsLeftAloneOutsidePlayingOrWhenSwitchedOff) {
  put_ball(500.f, 2100.f);
  update_at(0);
  EXPECT_FALSE(update_at(10).ball.has_value()); // READY
  rules.ball_out = false;
  referee.reset();
  start_playing();
  EXPECT_FALSE(update_at(60).ball.has_value());
}

} // namespace
} // namespace touchline::sim
