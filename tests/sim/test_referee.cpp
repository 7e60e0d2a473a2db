// The referee's game states and clock, and goals: hand-worked on the SPL 2011 field.
#include <gtest/gtest.h>

#include <stdexcept>

#include "referee_fixture.hpp"

namespace touchline::sim {
namespace {

void expect_change(const StateChange& c, GameState from, GameState to, double seconds) {
  EXPECT_EQ(c.from, from);
  EXPECT_EQ(c.to, to);
  EXPECT_EQ(c.utime, at_s(seconds));
}

// --- states and the clock --------------------------------------------------------------

TEST_F(RefereeTest, StatesFollowEachOtherAfterTheirDurations) {
  EXPECT_TRUE(update_at(0).state_changes.empty());
  EXPECT_EQ(ref().state(), GameState::kInitial);
  EXPECT_TRUE(update_at(0.999).state_changes.empty());

  auto d = update_at(1.0); // initial_s = 1
  ASSERT_EQ(d.state_changes.size(), 1u);
  expect_change(d.state_changes[0], GameState::kInitial, GameState::kReady, 1.0);

  EXPECT_TRUE(update_at(45.999).state_changes.empty()); // ready_s = 45
  d = update_at(46.0);
  ASSERT_EQ(d.state_changes.size(), 1u);
  expect_change(d.state_changes[0], GameState::kReady, GameState::kSet, 46.0);

  EXPECT_TRUE(update_at(50.999).state_changes.empty()); // set_s = 5
  d = update_at(51.0);
  ASSERT_EQ(d.state_changes.size(), 1u);
  expect_change(d.state_changes[0], GameState::kSet, GameState::kPlaying, 51.0);
  EXPECT_EQ(ref().info().state, GameState::kPlaying);
}

TEST_F(RefereeTest, ChangesAreTimedExactlyWhateverTheUpdateRate) {
  update_at(0);
  // One late update covers three states: each change carries the utime it happened.
  const auto d = update_at(51.02);
  ASSERT_EQ(d.state_changes.size(), 3u);
  expect_change(d.state_changes[0], GameState::kInitial, GameState::kReady, 1.0);
  expect_change(d.state_changes[1], GameState::kReady, GameState::kSet, 46.0);
  expect_change(d.state_changes[2], GameState::kSet, GameState::kPlaying, 51.0);
  // 20 ms played: 599.98 s left, shown rounded up.
  EXPECT_EQ(ref().info().secs_remaining, 600);
}

TEST_F(RefereeTest, CameraFrameUpdatesEndTheHalfAtExactlyHalfSecondsOfPlay) {
  rules.game_stuck_s = 0; // whole halves without a touch: the clock alone
  // Updates at every 30 Hz frame start (33.3 ms apart, not dividing the durations).
  std::vector<StateChange> changes;
  for (int64_t frame = 0; frame_start_utime(frame) <= at_s(651.5); ++frame) {
    input.utime = frame_start_utime(frame);
    for (const auto& c : ref().update(input).state_changes) changes.push_back(c);
  }
  ASSERT_EQ(changes.size(), 4u);
  expect_change(changes[0], GameState::kInitial, GameState::kReady, 1.0);
  expect_change(changes[1], GameState::kReady, GameState::kSet, 46.0);
  expect_change(changes[2], GameState::kSet, GameState::kPlaying, 51.0);
  expect_change(changes[3], GameState::kPlaying, GameState::kInitial, 651.0); // 51 + half_s 600
  EXPECT_FALSE(ref().info().first_half);
}

TEST_F(RefereeTest, ClockCountsDownOnlyWhilePlaying) {
  EXPECT_EQ((update_at(0), ref().info().secs_remaining), 600);
  update_at(30); // READY: the clock stands
  EXPECT_EQ(ref().info().secs_remaining, 600);
  update_at(kKickOffS + 10.5);
  EXPECT_EQ(ref().info().secs_remaining, 590); // 589.5 s left, rounded up

  put_ball(3100.f, 0.f); // goal at 61.5 s: READY until 106.5, SET until 111.5
  update_at(61.5);
  EXPECT_EQ(ref().state(), GameState::kReady);
  put_ball(0.f, 0.f);
  update_at(100);
  EXPECT_EQ(ref().info().secs_remaining, 590);
  update_at(111.5 + 20);
  EXPECT_EQ(ref().state(), GameState::kPlaying);
  EXPECT_EQ(ref().info().secs_remaining, 570);
}

TEST_F(RefereeTest, ZeroDurationsPassStraightThrough) {
  rules.initial_s = rules.ready_s = rules.set_s = 0;
  const auto d = update_at(7);
  ASSERT_EQ(d.state_changes.size(), 3u);
  EXPECT_EQ(d.state_changes[2].to, GameState::kPlaying);
  EXPECT_EQ(d.state_changes[2].utime, at_s(7));
}

TEST_F(RefereeTest, HalfTimeGivesTheSecondHalfWithTheOtherTeamKickingOff) {
  start_playing();
  EXPECT_EQ(ref().info().kickoff_team, 0);
  put_ball(700.f, -300.f);
  auto d = update_at(kKickOffS + 600);
  ASSERT_EQ(d.state_changes.size(), 1u);
  expect_change(d.state_changes[0], GameState::kPlaying, GameState::kInitial, 651.0);
  GameInfo info = ref().info();
  EXPECT_FALSE(info.first_half);
  EXPECT_EQ(info.kickoff_team, 1);
  EXPECT_EQ(info.secs_remaining, 600);
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->why, BallPlacement::Why::kKickOff);
  EXPECT_EQ(d.ball->x_mm, 0.f);
  EXPECT_EQ(d.ball->y_mm, 0.f);
  apply(d);

  // The second half runs the same sequence: READY at 652, SET at 697, PLAYING at 702.
  d = update_at(702);
  ASSERT_EQ(d.state_changes.size(), 3u);
  expect_change(d.state_changes[2], GameState::kSet, GameState::kPlaying, 702.0);
  EXPECT_EQ(ref().info().secs_remaining, 600);
}

TEST_F(RefereeTest, FullTimeFinishesTheMatchForGood) {
  rules.game_stuck_s = 0; // whole halves without a touch: the clock alone
  start_playing();
  update_at(702); // second half PLAYING from 702 s
  auto d = update_at(1301.999);
  EXPECT_TRUE(d.state_changes.empty());
  EXPECT_EQ(ref().info().secs_remaining, 1);
  d = update_at(1302);
  ASSERT_EQ(d.state_changes.size(), 1u);
  expect_change(d.state_changes[0], GameState::kPlaying, GameState::kFinished, 1302.0);
  EXPECT_EQ(ref().info().secs_remaining, 0);
  EXPECT_FALSE(ref().may_move(RobotId{0, 2}));

  put_ball(3100.f, 0.f); // nothing counts any more
  d = update_at(5000);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(ref().state(), GameState::kFinished);
  EXPECT_EQ(ref().info().score[0], 0);
}

TEST_F(RefereeTest, SecondKickOffTeamSettingIsHonoured) {
  rules.first_kickoff_team = 1;
  start_playing();
  EXPECT_EQ(ref().info().kickoff_team, 1);
  update_at(kKickOffS + 600);
  EXPECT_EQ(ref().info().kickoff_team, 0);
}

TEST_F(RefereeTest, RobotsMayMoveOnlyInReadyAndPlaying) {
  const RobotId id{0, 3};
  update_at(0);
  EXPECT_FALSE(ref().may_move(id)); // INITIAL
  update_at(1);
  EXPECT_TRUE(ref().may_move(id)); // READY
  update_at(46);
  EXPECT_FALSE(ref().may_move(id)); // SET
  update_at(51);
  EXPECT_TRUE(ref().may_move(id)); // PLAYING
}

TEST_F(RefereeTest, TimeGoingBackIsAnError) {
  update_at(10);
  EXPECT_THROW(update_at(9.9), std::invalid_argument);
}

TEST(Referee, BadSetupIsRefused) {
  RulesDef bad;
  bad.ready_s = -1;
  EXPECT_THROW(Referee(Field{}, bad, 4, 65.f), ConfigError);
  EXPECT_THROW(Referee(Field{}, RulesDef{}, 0, 65.f), std::invalid_argument);
  EXPECT_THROW(Referee(Field{}, RulesDef{}, 4, 0.f), std::invalid_argument);
}

TEST_F(RefereeTest, InputOrderDoesNotChangeTheDecisions) {
  // Two pushes and a leaver listed in opposite orders give identical decisions.
  rules.pushing_model = "thesis"; // standing robots: the thesis calls the push at first contact
  const auto scenario = [&](bool reversed) {
    referee.reset();
    input = RefereeInput{};
    put_ball(-2500.f, -1500.f);
    std::vector<RobotOnField> robots = {
        {RobotId{0, 2}, Pose2D{0.f, 1000.f, 0.f}, true},    {RobotId{1, 2}, Pose2D{200.f, 1000.f, 0.f}, true},
        {RobotId{0, 3}, Pose2D{0.f, -500.f, 0.f}, true},    {RobotId{1, 3}, Pose2D{200.f, -500.f, 0.f}, true},
        {RobotId{1, 4}, Pose2D{500.f, -2300.f, 0.f}, true},
    };
    if (reversed) std::reverse(robots.begin(), robots.end());
    input.robots = robots;
    start_playing();
    return update_at(60);
  };
  const auto a = scenario(false), b = scenario(true);
  ASSERT_EQ(a.penalties.size(), 3u);
  ASSERT_EQ(a.penalties.size(), b.penalties.size());
  for (size_t i = 0; i < a.penalties.size(); ++i) {
    EXPECT_EQ(a.penalties[i].robot, b.penalties[i].robot);
    EXPECT_EQ(a.penalties[i].kind, b.penalties[i].kind);
  }
}

// --- goals -----------------------------------------------------------------------------

TEST_F(RefereeTest, TeamZeroScoresInThePlusXGoal) {
  start_playing();
  put_ball(3000.f + 32.5f + 10.f, 200.f); // wholly 10 mm behind the goal line
  const auto d = update_at(60);
  ASSERT_EQ(d.goals.size(), 1u);
  EXPECT_EQ(d.goals[0].team, 0);
  EXPECT_EQ(d.goals[0].utime, at_s(60));
  const GameInfo info = ref().info();
  EXPECT_EQ(info.score[0], 1);
  EXPECT_EQ(info.score[1], 0);
  EXPECT_EQ(info.state, GameState::kReady);
  EXPECT_EQ(info.kickoff_team, 1); // the conceding team
  ASSERT_EQ(d.state_changes.size(), 1u);
  expect_change(d.state_changes[0], GameState::kPlaying, GameState::kReady, 60.0);
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->why, BallPlacement::Why::kKickOff);
  EXPECT_EQ(d.ball->x_mm, 0.f);
  EXPECT_EQ(d.ball->y_mm, 0.f);
}

TEST_F(RefereeTest, TeamOneScoresInTheMinusXGoal) {
  start_playing();
  put_ball(-3000.f - 32.5f - 10.f, -600.f);
  const auto d = update_at(60);
  ASSERT_EQ(d.goals.size(), 1u);
  EXPECT_EQ(d.goals[0].team, 1);
  EXPECT_EQ(ref().info().score[1], 1);
  EXPECT_EQ(ref().info().score[0], 0);
  EXPECT_EQ(ref().info().kickoff_team, 0);
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->x_mm, 0.f);
}

TEST_F(RefereeTest, BallOnTheGoalLineButNotWhollyOverIsNoGoal) {
  start_playing();
  put_ball(3000.f, 0.f); // centre on the line's outer edge
  auto d = update_at(52);
  EXPECT_TRUE(d.goals.empty());
  EXPECT_FALSE(d.ball.has_value()); // not out either
  put_ball(3000.f + 32.5f, 0.f); // its edge just touches the line
  d = update_at(53);
  EXPECT_TRUE(d.goals.empty());
  EXPECT_FALSE(d.ball.has_value());
  put_ball(3000.f + 33.5f, 0.f); // 1 mm wholly over
  EXPECT_EQ(update_at(54).goals.size(), 1u);
}

TEST_F(RefereeTest, WhollyOverTheGoalLineBesideTheGoalIsNoGoal) {
  start_playing();
  put_ball(3040.f, 800.f); // past the goal line, outside the posts (goal half-width 700)
  const auto d = update_at(60);
  EXPECT_TRUE(d.goals.empty());
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->why, BallPlacement::Why::kBallOut);
}

TEST_F(RefereeTest, NoGoalsOutsidePlaying) {
  update_at(0);
  put_ball(3100.f, 0.f);
  EXPECT_TRUE(update_at(10).goals.empty()); // READY
  EXPECT_TRUE(update_at(48).goals.empty()); // SET
  EXPECT_EQ(ref().info().score[0], 0);
}

TEST_F(RefereeTest, BallNudgedInReadyIsPutBackOnTheCentreSpotAtSet) {
  start_playing();
  put_ball(3100.f, 0.f);
  apply(update_at(60)); // goal: READY until 105, ball on the centre spot
  put_ball(150.f, -40.f); // a robot walking to its position touched it
  const auto d = update_at(105);
  EXPECT_EQ(ref().state(), GameState::kSet);
  ASSERT_TRUE(d.ball.has_value());
  EXPECT_EQ(d.ball->why, BallPlacement::Why::kKickOff);
  EXPECT_EQ(d.ball->x_mm, 0.f);
  EXPECT_EQ(d.ball->y_mm, 0.f);
}

TEST_F(RefereeTest, FirstKickOffBallStaysWhereTheMatchPutIt) {
  put_ball(1000.f, 500.f); // e.g. match.ball_start elsewhere for an experiment
  update_at(0);
  const auto d = update_at(46); // SET of the first kick-off
  EXPECT_EQ(ref().state(), GameState::kSet);
  EXPECT_FALSE(d.ball.has_value());
}

} // namespace
} // namespace touchline::sim
