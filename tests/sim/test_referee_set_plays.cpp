// The referee's set plays (rules.set_plays) and STANDBY (rules.standby_s), hand-worked on
// the SPL 2020 field: half length 4500, half width 3000, goal box 600 deep and 2200 wide,
// penalty area 1650 deep and 4000 wide, penalty marks 1300 from the goal lines. Team 0
// defends the goal at -x.
#include <gtest/gtest.h>

#include "referee_fixture.hpp"

namespace touchline::sim {
namespace {

const RobotId kRed2{0, 2}, kBlue2{1, 2}, kBlueGoalie{1, 1};

class SetPlays : public RefereeTest {
 protected:
  void SetUp() override {
    field = Field{spl2020_field()};
    rules.set_plays = true;
  }
  /// The ball at (x, y) during PLAYING, last touched by `team`: the decision it gives.
  RefereeDecision ball_out_at(float x, float y, int team, float vx = 0, float vy = 0) {
    if (!referee) start_playing();
    put_ball(x, y, vx, vy);
    input.last_touch_team = team;
    now_s += 1;
    return update_at(now_s);
  }
  double now_s = kKickOffS;
};

void expect_set_play(const RefereeDecision& d, SetPlay set_play, int team, float x, float y) {
  ASSERT_EQ(d.set_plays.size(), 1u);
  EXPECT_EQ(d.set_plays[0].set_play, set_play) << to_string(d.set_plays[0].set_play);
  EXPECT_EQ(d.set_plays[0].team, team);
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->why, BallPlacement::Why::kSetPlay);
  EXPECT_NEAR(d.ball->x_mm, x, 1e-3f);
  EXPECT_NEAR(d.ball->y_mm, y, 1e-3f);
}

// --- a ball out -------------------------------------------------------------------------

TEST_F(SetPlays, OverATouchlineTheOpponentsOfTheLastToucherKickItInWhereItLeft) {
  expect_set_play(ball_out_at(500.f, 3060.f, 0), SetPlay::kKickIn, 1, 500.f, 3000.f);
  EXPECT_EQ(ref().info().set_play, SetPlay::kKickIn);
  EXPECT_EQ(ref().info().set_play_team, 1);
  EXPECT_EQ(ref().info().drop_in_s, -1); // a set play is no drop-in: the GameController tells it as the set play
  // Traced back along its path: moving (-400, -100) mm/s it is 60 mm past y = -3000, so it
  // crossed 0.6 s ago, 240 mm further +x: at x = -900.
  expect_set_play(ball_out_at(-1140.f, -3060.f, 1, -400.f, -100.f), SetPlay::kKickIn, 0, -900.f, -3000.f);
}

TEST_F(SetPlays, AKickInNobodyTouchedGoesToTheTeamWhoseHalfItLeftFrom) {
  expect_set_play(ball_out_at(-500.f, 3060.f, -1), SetPlay::kKickIn, 0, -500.f, 3000.f);
  expect_set_play(ball_out_at(500.f, 3060.f, -1), SetPlay::kKickIn, 1, 500.f, 3000.f);
}

TEST_F(SetPlays, OverAGoalLineByTheAttackersTheDefendersTakeAGoalKickFromTheGoalBoxCorner) {
  // Past team 1's goal line (+x), wide of the goal, last touched by team 0: goal kick for team 1.
  expect_set_play(ball_out_at(4560.f, 1500.f, 0), SetPlay::kGoalKick, 1, 3900.f, 1100.f);
  expect_set_play(ball_out_at(-4560.f, -1500.f, 1), SetPlay::kGoalKick, 0, -3900.f, -1100.f);
}

TEST_F(SetPlays, OverTheirOwnGoalLineByTheDefendersTheAttackersTakeACornerKick) {
  expect_set_play(ball_out_at(4560.f, 1500.f, 1), SetPlay::kCornerKick, 0, 4500.f, 3000.f);
  expect_set_play(ball_out_at(-4560.f, -800.f, 0), SetPlay::kCornerKick, 1, -4500.f, -3000.f);
}

TEST_F(SetPlays, WithoutSetPlaysTheBallOutRuleIsThe2011One) {
  rules.set_plays = false;
  const RefereeDecision d = ball_out_at(500.f, 3060.f, 0);
  EXPECT_TRUE(d.set_plays.empty());
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->why, BallPlacement::Why::kBallOut);
  EXPECT_EQ(ref().info().set_play, SetPlay::kNone);
  EXPECT_EQ(ref().info().set_play_team, -1);
}

// --- how a set play ends ----------------------------------------------------------------

TEST_F(SetPlays, ASetPlayEndsWhenItsTeamTouchesTheBall) {
  ball_out_at(500.f, 3060.f, 0); // kick-in for team 1
  put_ball(500.f, 3000.f);
  input.touched_by_team = {{true, false}}; // the other team touching it ends nothing
  EXPECT_TRUE(update_at(now_s + 1).set_plays.empty());
  EXPECT_EQ(ref().info().set_play, SetPlay::kKickIn);

  input.touched_by_team = {{false, true}};
  const RefereeDecision d = update_at(now_s + 2);
  ASSERT_EQ(d.set_plays.size(), 1u);
  EXPECT_EQ(d.set_plays[0].set_play, SetPlay::kNone);
  EXPECT_EQ(d.set_plays[0].team, -1);
  EXPECT_EQ(d.set_plays[0].utime, at_s(now_s + 2));
  EXPECT_EQ(ref().info().set_play, SetPlay::kNone);
  EXPECT_EQ(ref().info().set_play_team, -1);
}

TEST_F(SetPlays, ASetPlayEndsAfterSetPlaySeconds) {
  rules.set_play_s = 30.f;
  ball_out_at(500.f, 3060.f, 0); // at 52 s
  put_ball(500.f, 3000.f);
  EXPECT_TRUE(update_at(now_s + 29.9).set_plays.empty());
  const RefereeDecision d = update_at(now_s + 30.0);
  ASSERT_EQ(d.set_plays.size(), 1u);
  EXPECT_EQ(d.set_plays[0].set_play, SetPlay::kNone);
}

TEST_F(SetPlays, AGoalEndsTheSetPlayWithPlaying) {
  ball_out_at(-4560.f, -1500.f, 1); // goal kick for team 0
  put_ball(4600.f, 0.f);            // then straight into team 1's goal
  const RefereeDecision d = update_at(now_s + 1);
  ASSERT_EQ(d.goals.size(), 1u);
  ASSERT_EQ(d.set_plays.size(), 1u);
  EXPECT_EQ(d.set_plays[0].set_play, SetPlay::kNone);
  EXPECT_EQ(ref().state(), GameState::kReady);
  EXPECT_EQ(ref().info().set_play, SetPlay::kNone);
}

// --- fouls ------------------------------------------------------------------------------

TEST_F(SetPlays, APushIsAPushingFreeKickForTheFouledTeamWithTheBallLeftWhereItIs) {
  rules.pushing_model = "thesis"; // standing robots: the thesis calls the push at first contact
  put_ball(500.f, 2500.f);              // far from both: no contest
  put_robot(kRed2, 0.f, 1000.f, 0.f);
  put_robot(kBlue2, 200.f, 1000.f, 0.f); // red walks into blue's back
  start_playing();
  const RefereeDecision d = update_at(kKickOffS + 1);
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].robot, kRed2);
  ASSERT_EQ(d.set_plays.size(), 1u);
  EXPECT_EQ(d.set_plays[0].set_play, SetPlay::kPushingFreeKick);
  EXPECT_EQ(d.set_plays[0].team, 1);
  EXPECT_FALSE(d.ball.has_value());
}

TEST_F(SetPlays, APushFromInsideTheOwnPenaltyAreaIsAPenaltyKickFromTheMark) {
  rules.pushing_model = "thesis"; // standing robots: the thesis calls the push at first contact
  put_ball(-2000.f, 2500.f);
  put_robot(kRed2, -3800.f, 1500.f, 0.f);  // in team 0's penalty area (1650 deep, 2000 either side)
  put_robot(kBlue2, -3600.f, 1500.f, 0.f);
  start_playing();
  const RefereeDecision d = update_at(kKickOffS + 1);
  ASSERT_EQ(d.penalties.size(), 1u);
  expect_set_play(d, SetPlay::kPenaltyKick, 1, -3200.f, 0.f); // team 0's mark: 1300 in from -4500
}

TEST_F(SetPlays, WithoutAPenaltyAreaTheGoalBoxServesAsOne) {
  rules.pushing_model = "thesis"; // standing robots: the thesis calls the push at first contact
  field = Field{FieldDef{}}; // SPL 2011: no penalty area; goal box 600 deep, 2200 wide; marks 1800 in
  put_ball(0.f, 1800.f);
  put_robot(kBlueGoalie, 2700.f, 800.f, kPi); // in team 1's goal box (the goalie may be)
  put_robot(kRed2, 2500.f, 800.f, kPi);       // the goalie walks into red's back (facing -x)
  start_playing();
  const RefereeDecision d = update_at(kKickOffS + 1);
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].robot, kBlueGoalie);
  expect_set_play(d, SetPlay::kPenaltyKick, 0, 1200.f, 0.f);
}

// --- STANDBY ----------------------------------------------------------------------------

TEST_F(RefereeTest, StandbyComesBetweenInitialAndReadyForItsDuration) {
  rules.standby_s = 10.f;
  update_at(0);
  auto d = update_at(1.0);
  ASSERT_EQ(d.state_changes.size(), 1u);
  EXPECT_EQ(d.state_changes[0].to, GameState::kStandby);
  EXPECT_EQ(ref().info().state, GameState::kStandby);
  EXPECT_FALSE(ref().may_move(kRed2)); // robots stand in STANDBY
  EXPECT_TRUE(update_at(10.999).state_changes.empty());
  d = update_at(11.0);
  ASSERT_EQ(d.state_changes.size(), 1u);
  EXPECT_EQ(d.state_changes[0].from, GameState::kStandby);
  EXPECT_EQ(d.state_changes[0].to, GameState::kReady);
  EXPECT_TRUE(ref().may_move(kRed2));
}

TEST_F(RefereeTest, WithoutStandbyInitialGoesStraightToReady) {
  update_at(0);
  const auto d = update_at(1.0);
  ASSERT_EQ(d.state_changes.size(), 1u);
  EXPECT_EQ(d.state_changes[0].to, GameState::kReady);
}

} // namespace
} // namespace touchline::sim
