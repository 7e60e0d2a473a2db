#include "touchline/sim/match.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"

using namespace touchline;
using sim::ActOutcome;

namespace {

sim::WorldConfig small_config() {
  sim::WorldConfig config;
  config.match.team_size = 2;
  config.match.duration_s = 1;
  config.rules.referee = false; // scheduling only; the referee's part has tests of its own below
  return config;
}

RobotAct forward_act(RobotId id, int64_t frame, int ticks, float dx_mm) {
  RobotAct act;
  act.id = id;
  act.frame = frame;
  act.motion_ticks = ticks;
  for (int i = 0; i < ticks; ++i) act.ticks[i].left = act.ticks[i].right = {dx_mm, 0, 0};
  return act;
}

} // namespace

TEST(Match, FramesFollowTheThreeThreeFourTickPattern) {
  sim::Match match(small_config());
  match.start();
  std::vector<int> ticks;
  for (int i = 0; i < 6; ++i) {
    ticks.push_back(match.sense().motion_ticks);
    match.advance();
  }
  EXPECT_EQ(ticks, (std::vector<int>{3, 3, 4, 3, 3, 4}));
  EXPECT_EQ(match.utime(), 200000); // 6 frames = 20 ticks of 10 ms
  EXPECT_EQ(match.world().ticks(), 20);
}

TEST(Match, RobotsArePlacedInIdOrderWhateverTheJoinOrder) {
  sim::Match a(small_config()), b(small_config());
  a.join({1, 2}, 1, 0);
  a.join({0, 1}, 2, 0);
  b.join({0, 1}, 3, 0);
  b.join({1, 2}, 4, 0);
  a.start();
  b.start();
  EXPECT_EQ(a.world().state_hash(), b.world().state_hash());
  ASSERT_EQ(a.sense().robots.size(), 2u);
  EXPECT_EQ(a.sense().robots[0].id, (RobotId{0, 1}));
}

TEST(Match, AnActMovesTheRobotByItsFootMotions) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  const Pose2D start = match.sense().robots[0].truth;
  const int ticks = match.sense().motion_ticks;
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, ticks, 5.f), 9), ActOutcome::kApplied);
  match.advance();
  const Pose2D end = match.truth().robots[0].truth.body;
  // Forward in the body frame: the robot faces theta.
  const float moved = std::hypot(end.x_mm - start.x_mm, end.y_mm - start.y_mm);
  EXPECT_NEAR(moved, 5.f * static_cast<float>(ticks), 0.05f);
}

TEST(Match, TheGyroFeelsTheBodysTurnOverTheLastFrameWhateverTurnedIt) {
  sim::WorldConfig config = small_config();
  config.perception.gyro_turn_sd_rad = 0;
  sim::Match match(config);
  match.join({0, 1}, 9, 0);
  match.start();
  EXPECT_EQ(match.sense().robots[0].gyro_turn_rad, 0.f); // no frame before the first
  const Pose2D start = match.sense().robots[0].truth;
  match.advance();
  // Turned by something other than its own steps (a push, a foot caught on a post).
  match.world().place_robot(0, {start.x_mm, start.y_mm, normalise_angle(start.theta_rad + 0.3f)});
  EXPECT_NEAR(match.sense().robots[0].gyro_turn_rad, 0.3f, 1e-5f);
  EXPECT_NEAR(match.sense().robots[0].gyro_turn_rad, 0.3f, 1e-5f); // the frame's, however often asked
  match.advance();
  EXPECT_EQ(match.sense().robots[0].gyro_turn_rad, 0.f); // still since
}

TEST(Match, StaleAndUnknownActsAreIgnored) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  match.advance();
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, 3, 5.f), 9), ActOutcome::kStale);
  EXPECT_EQ(match.apply(forward_act({0, 1}, 1, 3, 5.f), 8), ActOutcome::kUnknown); // wrong instance
  EXPECT_EQ(match.apply(forward_act({0, 2}, 1, 3, 5.f), 9), ActOutcome::kUnknown); // never joined
  EXPECT_EQ(match.apply(forward_act({0, 1}, 5, 3, 5.f), 9), ActOutcome::kFuture);  // not sensed yet
}

TEST(Match, ASecondAnswerToAFrameIsADuplicateAndMovesNothing) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  const Pose2D start = match.sense().robots[0].truth;
  const int ticks = match.sense().motion_ticks;
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, ticks, 5.f), 9), ActOutcome::kApplied);
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, ticks, 5.f), 9), ActOutcome::kDuplicate);
  match.advance();
  const Pose2D end = match.truth().robots[0].truth.body;
  EXPECT_NEAR(std::hypot(end.x_mm - start.x_mm, end.y_mm - start.y_mm), 5.f * static_cast<float>(ticks), 0.05f);
  EXPECT_EQ(match.roster().find({0, 1})->frames_answered, 1);
  // The same repeat arriving after the world moved on is still a duplicate, not a late answer.
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, ticks, 5.f), 9), ActOutcome::kDuplicate);
}

TEST(Match, FootMotionNoRobotCouldMakeIsRefused) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, 3, 1e30f), 9), ActOutcome::kImplausible);
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, 3, sim::kMaxFootTravelPerTickMm + 1.f), 9), ActOutcome::kImplausible);
  RobotAct spinning = forward_act({0, 1}, 0, 3, 5.f);
  spinning.ticks[1].left.dtheta_rad = 2 * sim::kMaxFootTurnPerTickRad;
  EXPECT_EQ(match.apply(spinning, 9), ActOutcome::kImplausible);
  RobotAct head = forward_act({0, 1}, 0, 3, 5.f);
  head.head_pitch_rad = 10.f;
  EXPECT_EQ(match.apply(head, 9), ActOutcome::kImplausible);
  // A kick's fastest swing is well inside the limits.
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, 3, 16.f), 9), ActOutcome::kApplied);
}

TEST(Match, EveryFrameSteppedWithoutARobotsAnswerCountsAsMissed) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.join({0, 2}, 10, 0);
  match.start();
  for (int frame = 0; frame < 5; ++frame) {
    EXPECT_EQ(match.apply(forward_act({0, 2}, frame, match.sense().motion_ticks, 1.f), 10), ActOutcome::kApplied);
    if (frame == 0) match.time_out({0, 1});
    match.advance();
  }
  EXPECT_EQ(match.roster().find({0, 1})->frames_missed, 5);
  EXPECT_EQ(match.roster().find({0, 2})->frames_missed, 0);
  EXPECT_EQ(match.roster().find({0, 2})->frames_answered, 5);
}

TEST(Match, FreeRunningAppliesLateAnswersLate) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  match.advance(); // frame 0 passes with no answer: the robot stands
  const Pose2D before = match.truth().robots[0].truth.body;
  EXPECT_EQ(match.apply(forward_act({0, 1}, 0, 3, 5.f), 9, /*accept_late=*/true), ActOutcome::kApplied);
  match.advance();
  const Pose2D after = match.truth().robots[0].truth.body;
  EXPECT_NEAR(std::hypot(after.x_mm - before.x_mm, after.y_mm - before.y_mm), 15.f, 0.05f);
}

TEST(Match, TimedOutRobotStandsIsInactiveAndRejoinsWhenItAnswers) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.join({0, 2}, 10, 0);
  match.start();
  match.apply(forward_act({0, 1}, 0, 3, 5.f), 9);
  match.time_out({0, 1}); // queued motion is dropped
  EXPECT_EQ(match.active_robots(), (std::vector<RobotId>{{0, 2}}));
  const Pose2D before = match.sense().robots[0].truth;
  match.advance();
  const Pose2D after = match.truth().robots[0].truth.body;
  EXPECT_FLOAT_EQ(after.x_mm, before.x_mm);
  EXPECT_FLOAT_EQ(after.y_mm, before.y_mm);
  EXPECT_FALSE(match.sense().robots[0].active);
  EXPECT_EQ(match.roster().find({0, 1})->frames_missed, 1);

  EXPECT_EQ(match.apply(forward_act({0, 1}, 1, 3, 5.f), 9), ActOutcome::kRejoined);
  EXPECT_EQ(match.active_robots().size(), 2u);
}

TEST(Match, LateJoinerIsPlacedAtOnce) {
  sim::Match match(small_config());
  match.join({0, 1}, 1, 0);
  match.start();
  EXPECT_EQ(match.sense().robots.size(), 1u);
  EXPECT_TRUE(match.join({1, 1}, 2, 0).accepted);
  EXPECT_EQ(match.sense().robots.size(), 2u);
}

TEST(Match, FinishesAfterItsDuration) {
  sim::Match match(small_config()); // 1 s
  match.start();
  int frames = 0;
  while (!match.finished()) {
    match.advance();
    ++frames;
  }
  EXPECT_EQ(frames, 30);
}

TEST(Match, BehaviourCpuTimeIsAccumulatedPerRobot) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  for (int64_t cpu : {100, 300, 200}) {
    RobotAct act = forward_act({0, 1}, match.frame(), match.sense().motion_ticks, 0.f);
    act.behaviour_cpu_us = cpu;
    match.apply(act, 9);
    match.advance();
  }
  const sim::Member* member = match.roster().find({0, 1});
  EXPECT_EQ(member->behaviour_cpu_us_mean(), 200);
  EXPECT_EQ(member->behaviour_cpu_us_max, 300);
}

TEST(Match, BallStartsWhereTheConfigSays) {
  sim::WorldConfig config = small_config();
  config.match.ball_start_x_mm = 1200;
  config.match.ball_start_y_mm = -400;
  sim::Match match(config);
  match.start();
  EXPECT_FLOAT_EQ(match.world().ball().x_mm, 1200);
  EXPECT_FLOAT_EQ(match.world().ball().y_mm, -400);
}

namespace {
sim::WorldConfig refereed_config() {
  sim::WorldConfig config;
  config.match.team_size = 1;
  config.rules.initial_s = 1;
  config.rules.ready_s = 2;
  config.rules.set_s = 1;
  return config;
}
} // namespace

TEST(Match, RefereeHoldsRobotsStillInInitialAndSetAndTellsTheGame) {
  sim::Match match(refereed_config());
  match.join({0, 1}, 9, 0);
  match.start();
  EXPECT_EQ(match.sense().game.state, GameState::kInitial);
  const Pose2D start = match.truth().robots[0].truth.body;
  for (int f = 0; f < 20; ++f) { // INITIAL: the robot asks to walk but stays put
    match.apply(forward_act({0, 1}, match.frame(), ticks_in_frame(match.frame()), 5.f), 9);
    match.advance();
  }
  EXPECT_FLOAT_EQ(match.truth().robots[0].truth.body.y_mm, start.y_mm);
  while (match.game().state != GameState::kReady) match.advance();
  match.apply(forward_act({0, 1}, match.frame(), ticks_in_frame(match.frame()), 5.f), 9);
  match.advance(); // READY: it walks
  EXPECT_GT(match.truth().robots[0].truth.body.y_mm, start.y_mm + 10);
  const auto events = match.take_events();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().kind, sim::MatchEvent::Kind::kStateChange);
  EXPECT_EQ(events.front().text, "READY");
  EXPECT_EQ(events.front().utime, 1000000); // exactly when INITIAL ran out
}

/// An act of robot `id` that moves only its left foot forward by dx_mm each tick.
RobotAct left_foot_act(RobotId id, int64_t frame, float dx_mm) {
  RobotAct act = forward_act(id, frame, ticks_in_frame(frame), 0.f);
  for (int i = 0; i < act.motion_ticks; ++i) act.ticks[i].left.dx_mm = dx_mm;
  return act;
}

// A step the referee stops (INITIAL holds the robot still) moves no foot, but the walk moved
// its legs: when the walk next lifts that foot (READY), the legs put it where the walk's steps
// did, well ahead of the other foot, not just the little the walk now moves it.
TEST(Match, AStepTheRefereeStoppedStillSetsTheStanceTheLegsHold) {
  sim::Match match(refereed_config());
  match.join({0, 1}, 9, 0);
  match.start();
  const auto ahead_mm = [&] { // the left foot's lead over the right along the body's heading
    const sim::RobotTruth r = match.truth().robots[0].truth;
    return (r.left_foot.x_mm - r.right_foot.x_mm) * std::cos(r.body.theta_rad) +
           (r.left_foot.y_mm - r.right_foot.y_mm) * std::sin(r.body.theta_rad);
  };
  for (int f = 0; f < 15; ++f) { // INITIAL: 15 frames of 2 mm a tick, 100 mm in all
    match.apply(left_foot_act({0, 1}, match.frame(), 2.f), 9);
    match.advance();
  }
  EXPECT_NEAR(ahead_mm(), 0.f, 1e-3f) << "held still";
  while (match.game().state != GameState::kReady) match.advance();
  for (int f = 0; f < 30; ++f) { // READY: 30 frames of 0.05 mm a tick, 5 mm
    match.apply(left_foot_act({0, 1}, match.frame(), 0.05f), 9);
    match.advance();
  }
  EXPECT_NEAR(ahead_mm(), 105.f, 0.5f);
}

TEST(Match, ABallOutWithSetPlaysIsAKickInTheRobotsSenseAndItsTeamsTouchEndsIt) {
  sim::WorldConfig config = refereed_config();
  config.rules.set_plays = true;
  sim::Match match(config);
  match.join({0, 1}, 9, 0);
  match.join({1, 1}, 8, 0);
  match.start();
  while (match.game().state != GameState::kPlaying) match.advance();
  const float hw = config.field.width_mm / 2;
  match.world().place_ball(-500, hw + 100, 0, 0); // wholly over team 0's side of the +y touchline
  match.advance();
  const GameInfo game = match.sense().game;
  EXPECT_EQ(game.set_play, SetPlay::kKickIn);
  EXPECT_EQ(game.set_play_team, 0); // nobody touched it: the team whose half it left from
  EXPECT_FLOAT_EQ(match.world().ball().y_mm, hw);
  std::vector<sim::MatchEvent> events = match.take_events();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back().kind, sim::MatchEvent::Kind::kSetPlay);
  EXPECT_EQ(events.back().team, 0);
  EXPECT_EQ(events.back().text, "kick-in for team 0");

  // Team 0's robot walks its foot into the ball: the set play is over.
  const sim::RobotTruth red = match.truth().robots[0].truth;
  match.world().place_ball(red.left_foot.x_mm + 120, red.left_foot.y_mm, -2000, 0);
  for (int f = 0; f < 10 && match.game().set_play != SetPlay::kNone; ++f) match.advance();
  EXPECT_EQ(match.game().set_play, SetPlay::kNone);
  events = match.take_events();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back().text, "set play over");
}

TEST(Match, AnUntouchedBallIsAStuckGameTheMatchTellsAndRestartsWithAKickOff) {
  sim::WorldConfig config = refereed_config();
  sim::Match match(config);
  match.join({0, 1}, 9, 0);
  match.join({1, 1}, 8, 0);
  match.start();
  while (match.game().state != GameState::kPlaying) match.advance();
  match.world().place_ball(800, 600, 0, 0);
  const int64_t kickoff_utime = match.utime();
  match.take_events();
  while (match.game().state == GameState::kPlaying) match.advance(); // nobody moves
  EXPECT_EQ(match.game().state, GameState::kReady);
  EXPECT_NEAR(static_cast<double>(match.utime() - kickoff_utime) * 1e-6, config.rules.game_stuck_s, 0.04);
  EXPECT_FLOAT_EQ(match.world().ball().x_mm, 0.f); // back on the centre spot
  const std::vector<sim::MatchEvent> events = match.take_events();
  const auto stuck = std::find_if(events.begin(), events.end(),
                                  [](const sim::MatchEvent& e) { return e.kind == sim::MatchEvent::Kind::kGameStuck; });
  ASSERT_NE(stuck, events.end());
  EXPECT_EQ(stuck->team, 1); // nobody touched it and team 0 kicked off: team 1's kick-off
  EXPECT_EQ(stuck->text, "game stuck (ball untouched for 30 s), kick-off for team 1");
}

TEST(Match, RobotsSeeThroughTheCameraAndTheSeedFixesTheNoise) {
  auto seen_from = [](uint64_t seed) {
    sim::WorldConfig config;
    config.match.team_size = 1;
    const Pose2D robot = sim::initial_pose(sim::Field(config.field), 1, {0, 1});
    config.match.ball_start_x_mm = robot.x_mm; // 800 mm in front of the robot on its touchline
    config.match.ball_start_y_mm = robot.y_mm + 800;
    sim::Match match(config, seed);
    match.join({0, 1}, 9, 0);
    match.start();
    return match.sense().robots[0].seen;
  };
  const auto a = seen_from(7), b = seen_from(7), c = seen_from(8);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a[0].kind, ObjectKind::kBall);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].distance_mm, b[i].distance_mm);
  EXPECT_NE(a[0].distance_mm, c.empty() ? -1.f : c[0].distance_mm);
}

TEST(Match, LocalisationErrorOfTheRobotsBeliefIsMeasuredAgainstTruth) {
  sim::Match match(small_config());
  match.join({0, 1}, 9, 0);
  match.start();
  for (int f = 0; f < 4; ++f) {
    RobotAct act = forward_act({0, 1}, match.frame(), ticks_in_frame(match.frame()), 0.f);
    const Pose2D truth = match.sense().robots[0].truth;
    act.localised = {truth.x_mm + 30, truth.y_mm - 40, truth.theta_rad + 0.1f}; // 50 mm, 0.1 rad off
    match.apply(act, 9);
    match.advance();
  }
  const sim::Member* member = match.roster().find({0, 1});
  EXPECT_NEAR(member->localisation_rms_mm(), 50, 1e-3);
  EXPECT_NEAR(member->localisation_rms_rad(), 0.1, 1e-6);
}

TEST(Match, TeamMessagesReachTeammatesThroughTheRadio) {
  sim::WorldConfig config = small_config();
  config.comm.loss_probability = 0;
  sim::Match match(config);
  match.join({0, 1}, 1, 0);
  match.join({0, 2}, 2, 0);
  match.start();
  RobotAct act = forward_act({0, 1}, match.frame(), ticks_in_frame(match.frame()), 0.f);
  act.team_message = {1, 2, 3};
  match.apply(act, 1);
  match.advance();
  std::vector<TeamMessageFrame> got;
  for (int f = 0; f < 6 && got.empty(); ++f) { // 100 ms of latency: 3 frames
    got = match.sense().robots[1].messages;
    match.advance();
  }
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].player, 1);
  EXPECT_EQ(got[0].data, (std::vector<uint8_t>{1, 2, 3}));
}

namespace {

/// One robot a team, straight to PLAYING, where the test puts them (no manual placement).
sim::WorldConfig one_a_side_playing() {
  sim::WorldConfig config;
  config.match.team_size = 1;
  config.rules.initial_s = config.rules.ready_s = config.rules.set_s = 0;
  config.rules.manual_placement = false;
  return config;
}

} // namespace

// Each robot feels where the other touches it: the one walked into from behind feels it on
// its back, the one behind on its right foot bumper; apart, neither feels anything.
TEST(Match, EachRobotFeelsWhereTheOtherTouchesIt) {
  sim::Match match(one_a_side_playing());
  match.join({0, 1}, 1, 0);
  match.join({1, 1}, 2, 0);
  match.start();
  match.world().place_robot(0, {0, 0, 0});
  match.world().place_robot(1, {-250, 20, 0}); // robot 0 is 250 mm ahead of it, a little to its right
  const SenseFrame touching = match.sense();
  EXPECT_TRUE(touching.find({0, 1})->touch.back);
  EXPECT_TRUE(touching.find({1, 1})->touch.front_right);
  match.world().place_robot(1, {-1000, 0, 0});
  const SenseFrame apart = match.sense();
  EXPECT_FALSE(apart.find({0, 1})->touch.any());
  EXPECT_FALSE(apart.find({1, 1})->touch.any());
}

TEST(Match, PushingIsPenalisedAndThePushedRobotFallsThenGetsUp) {
  sim::WorldConfig config = one_a_side_playing();
  config.rules.fall_probability = 1;
  config.rules.getup_s = 2;
  config.match.ball_start_x_mm = 2500; // far from both: not contesting it
  config.rules.pushing_model = "thesis"; // robots put down in contact: a push at once, without a walk
  sim::Match match(config);
  match.join({0, 1}, 1, 0);
  match.join({1, 1}, 2, 0);
  match.start();
  match.advance();
  ASSERT_EQ(match.game().state, GameState::kPlaying);
  // Team 1's robot walks into the back of team 0's, both facing +x.
  match.world().place_robot(0, {0, 0, 0});
  match.world().place_robot(1, {-250, 0, 0});
  match.take_events();
  match.advance();
  const auto events = match.take_events();
  const auto penalty = std::find_if(events.begin(), events.end(),
                                    [](const sim::MatchEvent& e) { return e.kind == sim::MatchEvent::Kind::kPenalty; });
  ASSERT_NE(penalty, events.end());
  EXPECT_EQ(penalty->robot, (RobotId{1, 1}));
  EXPECT_EQ(penalty->text, "pushing");
  const auto fall = std::find_if(events.begin(), events.end(),
                                 [](const sim::MatchEvent& e) { return e.kind == sim::MatchEvent::Kind::kFall; });
  ASSERT_NE(fall, events.end());
  EXPECT_EQ(fall->robot, (RobotId{0, 1}));

  SenseFrame sense = match.sense();
  EXPECT_TRUE(sense.find({0, 1})->fallen);
  EXPECT_TRUE(sense.find({1, 1})->penalised);
  const Pose2D lying = match.truth().robots[0].truth.body;
  for (int f = 0; f < 30; ++f) { // it asks to walk but lies still
    match.apply(forward_act({0, 1}, match.frame(), ticks_in_frame(match.frame()), 5.f), 1);
    match.advance();
  }
  EXPECT_FLOAT_EQ(match.truth().robots[0].truth.body.x_mm, lying.x_mm);
  for (int f = 0; f < 40; ++f) match.advance(); // 2 s of get-up time are over
  EXPECT_FALSE(match.sense().find({0, 1})->fallen);
  match.apply(forward_act({0, 1}, match.frame(), ticks_in_frame(match.frame()), 5.f), 1);
  match.advance();
  EXPECT_GT(match.truth().robots[0].truth.body.x_mm, lying.x_mm);
}

TEST(Match, ARobotThatLostABallContestMayStepAwayButNotTowardsTheWinner) {
  sim::WorldConfig config = one_a_side_playing();
  config.rules.game_stuck_s = 0;
  sim::Match match(config);
  match.join({0, 1}, 1, 0);
  match.join({1, 1}, 2, 0);
  match.start();
  match.advance();
  ASSERT_EQ(match.game().state, GameState::kPlaying);
  // Facing each other over the ball, team 0's robot nearer it: team 1's lost the contest.
  match.world().place_ball(-20, 0);
  match.world().place_robot(0, {-100, 0, 0});
  match.world().place_robot(1, {150, 0, kPi});
  match.advance();
  const auto x_of_loser = [&] { return match.truth().robots[1].truth.body.x_mm; };
  const float before = x_of_loser();
  match.apply(forward_act({1, 1}, match.frame(), ticks_in_frame(match.frame()), 2.f), 2); // towards the winner
  match.advance();
  EXPECT_FLOAT_EQ(x_of_loser(), before);
  match.apply(forward_act({1, 1}, match.frame(), ticks_in_frame(match.frame()), -2.f), 2); // backwards, away
  match.advance();
  EXPECT_GT(x_of_loser(), before + 5.f);
}

namespace {

/// Everything a 4 v 4 match tells its robots and the world's state, frame by frame, with
/// the robots' answers (team messages every frame the radio allows) applied in the order
/// `order(frame, ids)` gives.
template <typename Order>
std::vector<std::vector<int64_t>> play_in_order(Order order) {
  sim::WorldConfig config;
  config.match.team_size = 4;
  config.rules.referee = false;
  config.comm.loss_probability = 0.4f;
  config.comm.max_rate_hz = 10;
  sim::Match match(config, 21);
  std::vector<RobotId> ids;
  for (int team = 0; team < 2; ++team)
    for (int player = 1; player <= 4; ++player) ids.push_back({team, player});
  for (size_t i = 0; i < ids.size(); ++i) match.join(ids[i], static_cast<int64_t>(i) + 1, 0);
  match.start();
  std::vector<std::vector<int64_t>> frames;
  for (int f = 0; f < 90; ++f) {
    const SenseFrame sense = match.sense();
    std::vector<int64_t> told;
    for (const RobotSense& robot : sense.robots) {
      told.push_back(static_cast<int64_t>(robot.seen.size()));
      for (const TeamMessageFrame& m : robot.messages) {
        told.insert(told.end(), {m.player, m.sent_utime});
        told.insert(told.end(), m.data.begin(), m.data.end());
      }
    }
    for (const RobotId& id : order(f, ids)) {
      const auto index = static_cast<int64_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
      RobotAct act = forward_act(id, match.frame(), ticks_in_frame(match.frame()), 2.f + static_cast<float>(index));
      act.team_message = {static_cast<uint8_t>(id.team), static_cast<uint8_t>(id.player), static_cast<uint8_t>(f)};
      match.apply(act, index + 1);
    }
    match.advance();
    told.push_back(static_cast<int64_t>(match.world().state_hash()));
    frames.push_back(told);
  }
  frames.push_back({match.comm().sent(), match.comm().lost(), match.comm().delivered()});
  return frames;
}

} // namespace

TEST(Match, TheOrderInWhichAnswersArriveChangesNothing) {
  // Over UDP the robots' answers arrive in any order; the match must be the same.
  const auto in_id_order = play_in_order([](int, std::vector<RobotId> ids) { return ids; });
  const auto shuffled = play_in_order([](int frame, std::vector<RobotId> ids) {
    std::rotate(ids.begin(), ids.begin() + (3 * frame) % static_cast<int>(ids.size()), ids.end());
    if (frame % 2 == 0) std::reverse(ids.begin(), ids.end());
    return ids;
  });
  ASSERT_EQ(in_id_order.size(), shuffled.size());
  for (size_t f = 0; f < in_id_order.size(); ++f) ASSERT_EQ(in_id_order[f], shuffled[f]) << "frame " << f;
  const auto& comm = in_id_order.back();
  EXPECT_GT(comm[1], 0);       // messages were lost
  EXPECT_GT(comm[2], comm[1]); // and more delivered
}
