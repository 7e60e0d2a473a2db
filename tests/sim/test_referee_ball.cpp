// The ball leaving the field: put back on the throw-in line (ball_out_inset_mm, 400 mm
// inside the touchline, ending throw_in_line_end_mm, 1000, short of the goal lines) as SPL
// 2011 has it. SPL 2011 field: half length 3000, half width 2000, goal half-width 700, posts
// 100 mm; ball radius 32.5 mm.
#include <gtest/gtest.h>
#include <functional>
#include <optional>

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

TEST_F(BallOut, OverATouchlineItGoesOnTheThrowInLineTowardsTheLastTouchersGoal) {
  expect_ball(put_back(500.f, 2040.f, 0), -500.f, 1600.f);  // team 0 defends -x
  expect_ball(put_back(500.f, 2040.f, 1), 1500.f, 1600.f);  // team 1 defends +x
  expect_ball(put_back(500.f, 2040.f, -1), 500.f, 1600.f);  // unknown: where it left
  expect_ball(put_back(-700.f, -2040.f, 1), 300.f, -1600.f); // the other touchline
  expect_ball(put_back(-700.f, -2040.f, 0), -1700.f, -1600.f);
}

TEST_F(BallOut, TheCrossingPointIsTracedBackAlongTheBallsPath) {
  // 100 mm past the touchline moving (1000, 1000) mm/s: it crossed 0.1 s ago at x = 500.
  expect_ball(put_back(600.f, 2100.f, -1, 1000.f, 1000.f), 500.f, 1600.f);
  // Bounced back off the wall (moving into the field): no way to trace, use x as it is.
  expect_ball(put_back(600.f, 2100.f, -1, 1000.f, -1000.f), 600.f, 1600.f);
}

TEST_F(BallOut, TheSetbackStopsAtTheThrowInLinesEnd) {
  expect_ball(put_back(2800.f, 2040.f, 1), 2000.f, 1600.f); // 1 m short of the goal line
  expect_ball(put_back(-2800.f, -2040.f, 0), -2000.f, -1600.f);
  expect_ball(put_back(1700.f, 2040.f, -1), 1700.f, 1600.f); // within it: where it crossed
}

TEST_F(BallOut, OverAGoalLineByTheAttackersItGoesToTheHalfwayLine) {
  // Team 0 attacks +x: on the throw-in line of the side it left.
  expect_ball(put_back(3040.f, 1500.f, 0), 0.f, 1600.f);
  expect_ball(put_back(-3040.f, -1200.f, 1), 0.f, -1600.f);
}

TEST_F(BallOut, OverAGoalLineByTheDefendersOrUnknownItGoesToTheThrowInLinesEnd) {
  expect_ball(put_back(3040.f, 1500.f, 1), 2000.f, 1600.f);
  expect_ball(put_back(3040.f, -900.f, -1), 2000.f, -1600.f);
  expect_ball(put_back(-3040.f, -720.f, 0), -2000.f, -1600.f);
}

TEST_F(BallOut, OverACornerTheLineCrossedFirstCounts) {
  // Last touched by team 0, attacking +x. 50 mm past the goal line and 80 mm past the
  // touchline. Moving (1000, 2000) mm/s it crossed the goal line 0.05 s ago, the touchline
  // 0.04 s ago: out over the goal line by an attacker, to the halfway line.
  expect_ball(put_back(3050.f, 2080.f, 0, 1000.f, 2000.f), 0.f, 1600.f);
  // Moving (2000, 1000) mm/s: the touchline 0.08 s ago, first; at x = 3050 - 160 = 2890,
  // set back 1 m.
  expect_ball(put_back(3050.f, 2080.f, 0, 2000.f, 1000.f), 1890.f, 1600.f);
}

TEST_F(BallOut, ASpotWithARobotOnItMovesAlongTheLineTheSetbacksWayUntilClear) {
  // Put into a foot, the ball was knocked out again at once. Team 0 touched it last: the
  // spot (-500, 1600) moves towards -x, the setback's way, until 200 mm from the robot.
  // Clear from x <= -673.6 (or >= -286.4): the 50 mm steps reach -700 before -300 is clear.
  put_robot({1, 2}, -480.f, 1550.f, 0.f);
  expect_ball(put_back(500.f, 2040.f, 0), -700.f, 1600.f);
  // A second robot there: -x is clear only from -949, +x from -286.4, so +x it is (-250).
  put_robot({0, 3}, -750.f, 1580.f, 0.f);
  expect_ball(put_back(500.f, 2040.f, 0), -250.f, 1600.f);
}

TEST_F(BallOut, AClearSpotOrAZeroClearanceLeavesTheSpot) {
  put_robot({1, 2}, -500.f, 1350.f, 0.f); // 250 mm inside the throw-in line: clear
  expect_ball(put_back(500.f, 2040.f, 0), -500.f, 1600.f);
  rules.ball_out_clearance_mm = 0.f;
  referee.reset();
  now_s = kKickOffS;
  put_robot({1, 2}, -500.f, 1600.f, 0.f);
  expect_ball(put_back(500.f, 2040.f, 0), -500.f, 1600.f);
}

TEST_F(BallOut, AMovedSpotStaysOnTheThrowInLine) {
  // On the line's end, the setback's way (+x) is past it: it goes the other way.
  put_robot({0, 2}, 2000.f, 1600.f, 0.f);
  expect_ball(put_back(2800.f, 2040.f, 1), 1800.f, 1600.f);
}

TEST_F(BallOut, TheThrowInLineIsConfigurable) {
  rules.ball_out_inset_mm = 0; // on the touchline
  rules.throw_in_line_end_mm = 0; // to the goal lines
  expect_ball(put_back(500.f, 2040.f, -1), 500.f, 2000.f);
  expect_ball(put_back(2800.f, 2040.f, 1), 3000.f, 2000.f);
  expect_ball(put_back(3040.f, 1500.f, 1), 3000.f, 2000.f);
}

TEST_F(BallOut, TheGameControllerTellsWhoseBallWentOutAndHowLongAgo) {
  // As the SPL 2011 GameController's dropInTeam and dropInTime: none before the first.
  start_playing();
  EXPECT_EQ(ref().info().drop_in_team, -1);
  EXPECT_EQ(ref().info().drop_in_s, -1);
  put_back(500.f, 2040.f, 1);
  EXPECT_EQ(ref().info().drop_in_team, 1);
  EXPECT_EQ(ref().info().drop_in_s, 0);
  put_ball(0.f, 0.f);
  update_at(now_s + 2.5);
  EXPECT_EQ(ref().info().drop_in_s, 2); // whole seconds
  now_s += 3;
  put_back(500.f, -2040.f, -1); // a ball nobody was seen to touch: the team is not known
  EXPECT_EQ(ref().info().drop_in_team, -1);
  EXPECT_EQ(ref().info().drop_in_s, 0);
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

// --- a stuck game (Global Game Stuck) ---------------------------------------------------

namespace touchline::sim {
namespace {

class GameStuckTest : public RefereeTest {
 protected:
  /// Updates every frame (1/30 s) from `from_s` to `to_s`; the first stuck game, if any.
  std::optional<GameStuck> play_until_stuck(double from_s, double to_s,
                                            const std::function<void(double)>& each_frame = {}) {
    for (double s = from_s; s <= to_s; s += 1.0 / 30) {
      if (each_frame) each_frame(s);
      const RefereeDecision d = update_at(s);
      input.touched_by_team = {false, false};
      if (d.game_stuck) return d.game_stuck;
    }
    return std::nullopt;
  }
};

TEST_F(GameStuckTest, NoTouchForThirtySecondsRestartsWithAKickOffForTheOpponentsOfTheLastToucher) {
  put_ball(800, 300);
  start_playing();
  input.last_touch_team = 0;
  const auto stuck = play_until_stuck(kKickOffS + 0.1, kKickOffS + 40);
  ASSERT_TRUE(stuck);
  EXPECT_NEAR(static_cast<double>(stuck->utime) / kSecond, kKickOffS + 30, 0.05);
  EXPECT_TRUE(stuck->ball_untouched);
  EXPECT_EQ(stuck->kickoff_team, 1);
  EXPECT_EQ(ref().state(), GameState::kReady);
  EXPECT_EQ(ref().info().kickoff_team, 1);
}

TEST_F(GameStuckTest, AWedgedBallIsStuckThoughRobotsKeepTouchingIt) {
  put_ball(-1200, 900);
  start_playing();
  input.last_touch_team = 1;
  // Touched every second, rattling within 100 mm of one spot.
  const auto stuck = play_until_stuck(kKickOffS + 0.1, kKickOffS + 40, [&](double s) {
    put_ball(-1200 + 100 * static_cast<float>(std::sin(s)), 900);
    if (std::fmod(s, 1.0) < 1.0 / 30) input.touched_by_team = {true, true};
  });
  ASSERT_TRUE(stuck);
  EXPECT_FALSE(stuck->ball_untouched);
  EXPECT_EQ(stuck->kickoff_team, 0);
}

TEST_F(GameStuckTest, ABallInPlayIsNotStuck) {
  put_ball(0, 0);
  start_playing();
  // Touched every 10 s and carried up and down the field: two minutes of play.
  const auto stuck = play_until_stuck(kKickOffS + 0.1, kKickOffS + 120, [&](double s) {
    put_ball(2000 * static_cast<float>(std::sin(s / 10)), 0);
    if (std::fmod(s, 10.0) < 1.0 / 30) input.touched_by_team = {true, false};
  });
  EXPECT_FALSE(stuck);
  EXPECT_EQ(ref().state(), GameState::kPlaying);
}

TEST_F(GameStuckTest, SwitchedOffItNeverFires) {
  rules.game_stuck_s = 0;
  put_ball(800, 300);
  start_playing();
  EXPECT_FALSE(play_until_stuck(kKickOffS + 0.1, kKickOffS + 100));
  EXPECT_EQ(ref().state(), GameState::kPlaying);
}

TEST_F(GameStuckTest, TheWatchStartsAgainAtEveryKickOff) {
  put_ball(800, 300);
  start_playing();
  ASSERT_TRUE(play_until_stuck(kKickOffS + 0.1, kKickOffS + 40)); // stuck at 81 s: READY, SET, PLAYING
  const double second_kickoff_s = kKickOffS + 30 + rules.ready_s + rules.set_s;
  update_at(second_kickoff_s);
  ASSERT_EQ(ref().state(), GameState::kPlaying);
  const auto stuck = play_until_stuck(second_kickoff_s + 0.1, second_kickoff_s + 40);
  ASSERT_TRUE(stuck);
  EXPECT_NEAR(static_cast<double>(stuck->utime) / kSecond, second_kickoff_s + 30, 0.05);
}

} // namespace
} // namespace touchline::sim
