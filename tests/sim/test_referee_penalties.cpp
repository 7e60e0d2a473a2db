// The referee's penalties: pushing (thesis 2.2.4), illegal defender, leaving the field;
// removal to the bench and re-entry after removal_s. SPL 2011 field: half length 3000,
// half width 2000, goal box 600 deep and 2200 wide, penalty marks 1800 from the goal lines.
#include <gtest/gtest.h>

#include "referee_fixture.hpp"

namespace touchline::sim {
namespace {

const RobotId kRed2{0, 2}, kRed3{0, 3}, kRed4{0, 4}, kRedGoalie{0, 1};
const RobotId kBlue2{1, 2}, kBlue3{1, 3};

/// Red 2 walks into the back of blue 2 (both facing +x, red 200 mm behind), far from the ball,
/// as the thesis judges it (rules.pushing_model = thesis): from the headings alone, at the
/// first frame of contact, so these robots need not move. (WalkingInto below: the default.)
class Pushing : public RefereeTest {
 protected:
  void SetUp() override {
    rules.pushing_model = "thesis";
    put_ball(500.f, 1500.f); // over 500 mm from both robots: not contesting
    put_robot(kRed2, 0.f, 1000.f, 0.f);
    put_robot(kBlue2, 200.f, 1000.f, 0.f); // 200 mm ahead: in contact (< 300)
  }
};

// --- pushing ---------------------------------------------------------------------------

TEST_F(Pushing, ThePusherIsTakenOffToItsBench) {
  update_at(0);
  const auto d = update_at(kKickOffS + 9); // 60 s, PLAYING
  ASSERT_EQ(d.penalties.size(), 1u);
  const Penalty& p = d.penalties[0];
  EXPECT_EQ(p.robot, kRed2);
  EXPECT_EQ(p.kind, PenaltyKind::kPushing);
  EXPECT_EQ(p.since_utime, at_s(60));
  EXPECT_EQ(p.until_utime, at_s(90)); // removal_s = 30
  ASSERT_EQ(d.placements.size(), 1u);
  EXPECT_EQ(d.placements[0].robot, kRed2);
  // Bench: half way across the 700 mm border beyond team 0's touchline, spot 2 of 5.
  expect_pose(d.placements[0].pose, -1200.f, -2350.f, kPi / 2);
  EXPECT_FALSE(field.inside_lines(d.placements[0].pose.x_mm, d.placements[0].pose.y_mm));
  EXPECT_TRUE(ref().penalised(kRed2));
  EXPECT_FALSE(ref().penalised(kBlue2));
  EXPECT_FALSE(ref().may_move(kRed2));
  EXPECT_TRUE(ref().may_move(kBlue2));
  ASSERT_TRUE(ref().penalty(kRed2).has_value());
  EXPECT_EQ(ref().penalty(kRed2)->kind, PenaltyKind::kPushing);
  EXPECT_FALSE(ref().penalty(kBlue2).has_value());
}

TEST_F(Pushing, ThePusherReEntersAfterRemovalOnTheTouchlineFartherFromTheBall) {
  update_at(0);
  apply(update_at(60)); // red 2 to the bench
  // On the bench it is off the field: that is not a second penalty.
  auto d = update_at(89.99);
  EXPECT_TRUE(d.penalties.empty());
  EXPECT_TRUE(d.released.empty());
  EXPECT_TRUE(ref().penalised(kRed2));

  put_ball(500.f, 1500.f); // ball on the +y side: re-enter on the -y touchline
  d = update_at(90);
  ASSERT_EQ(d.released.size(), 1u);
  EXPECT_EQ(d.released[0], kRed2);
  ASSERT_EQ(d.placements.size(), 1u);
  // Own half, level with the own penalty mark (3000 - 1800), facing into the field.
  expect_pose(d.placements[0].pose, -1200.f, -2000.f, kPi / 2);
  EXPECT_TRUE(d.penalties.empty());
  EXPECT_FALSE(ref().penalised(kRed2));
  EXPECT_TRUE(ref().may_move(kRed2));
}

TEST_F(Pushing, ReEntryIsOnThePlusYTouchlineWhenTheBallIsOnTheMinusYSide) {
  update_at(0);
  apply(update_at(60));
  put_ball(500.f, -1500.f);
  const auto d = update_at(90);
  ASSERT_EQ(d.placements.size(), 1u);
  expect_pose(d.placements[0].pose, -1200.f, 2000.f, -kPi / 2);
}

TEST_F(RefereeTest, TeamOnePusherGoesToItsOwnBenchAndHalf) {
  rules.pushing_model = "thesis";
  put_ball(-500.f, 1500.f);
  put_robot(kBlue2, 0.f, 1000.f, kPi); // facing -x, behind red 2
  put_robot(kRed2, -200.f, 1000.f, kPi);
  update_at(0);
  auto d = update_at(60);
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].robot, kBlue2);
  expect_pose(d.placements[0].pose, 1200.f, 2350.f, -kPi / 2);
  apply(d);
  d = update_at(90);
  ASSERT_EQ(d.placements.size(), 1u);
  expect_pose(d.placements[0].pose, 1200.f, -2000.f, kPi / 2);
}

TEST_F(Pushing, OneCollisionGivesOnePenalty) {
  rules.removal_s = 1; // back in 1 s; pushing_cooldown_s = 5
  update_at(0);
  EXPECT_EQ(update_at(60).penalties.size(), 1u);
  // The match has not moved anyone yet: the same contact is seen again.
  EXPECT_TRUE(update_at(60.033).penalties.empty());
  EXPECT_EQ(update_at(61).released.size(), 1u);
  // Still (or again) in contact within the cooldown: no second penalty, for either robot.
  EXPECT_TRUE(update_at(61.5).penalties.empty());
  EXPECT_TRUE(update_at(64.99).penalties.empty());
  // Five seconds after the first: a new collision is a new penalty.
  const auto d = update_at(65);
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].robot, kRed2);
}

TEST_F(Pushing, NoPushingPenaltiesInReadyOrSet) {
  update_at(0);
  EXPECT_TRUE(update_at(10).penalties.empty()); // READY
  EXPECT_TRUE(update_at(48).penalties.empty()); // SET
  EXPECT_FALSE(ref().penalised(kRed2));
}

TEST_F(Pushing, TheRuleCanBeSwitchedOff) {
  rules.pushing = false;
  start_playing();
  EXPECT_TRUE(update_at(60).penalties.empty());
}

// --- pushing: walking into (the default rules.pushing_model) ---------------------------

/// Robots moved frame by frame (30 Hz) after the kick-off, far from the ball.
class WalkingInto : public RefereeTest {
 protected:
  static constexpr double kFrameS = 1.0 / 30;
  void SetUp() override { put_ball(-2500.f, -1500.f); }
  /// Updates frame by frame from `from_s` for `seconds`; before each update, `move`(t) puts
  /// the robots where they are t seconds in. Returns every penalty given.
  template <typename Move>
  std::vector<Penalty> play(double from_s, double seconds, Move move) {
    std::vector<Penalty> given;
    for (int k = 1; k * kFrameS <= seconds + 1e-9; ++k) {
      move(k * kFrameS);
      const RefereeDecision d = update_at(from_s + k * kFrameS);
      given.insert(given.end(), d.penalties.begin(), d.penalties.end());
      apply(d);
    }
    return given;
  }
};

TEST_F(WalkingInto, AStandingRobotWalkedIntoIsNotPenalisedTheWalkerIs) {
  // Red 2 stands facing +x; blue 2 walks on into it (facing -x, 100 mm/s) from 500 mm away:
  // in contact from 2 s on, a foul once that has lasted pushing_min_contact_s (1 s). Facing
  // each other, both square: the thesis names red (a tie goes to the lower id), the robot
  // that did not move.
  ASSERT_EQ(rules.pushing_min_contact_s, 1.f);
  put_robot(kRed2, 0.f, 0.f, 0.f);
  put_robot(kBlue2, 500.f, 0.f, kPi);
  start_playing();
  const auto walk = [&](double t) { put_robot(kBlue2, std::max(120.f, 500.f - 100.f * float(t)), 0.f, kPi); };
  const auto given = play(kKickOffS, 5, walk);
  ASSERT_EQ(given.size(), 1u);
  EXPECT_EQ(given[0].robot, kBlue2);
  EXPECT_EQ(given[0].kind, PenaltyKind::kPushing);
  EXPECT_NEAR(static_cast<double>(given[0].since_utime - at_s(kKickOffS)) * 1e-6, 3.0, 0.05);
  EXPECT_FALSE(ref().penalised(kRed2));

  // The thesis setting keeps its verdict: the stander, at the first frame of contact.
  rules.pushing_model = "thesis";
  referee.reset();
  put_robot(kRed2, 0.f, 0.f, 0.f);
  put_robot(kBlue2, 700.f, 0.f, kPi);
  start_playing();
  const auto thesis = play(kKickOffS, 5, walk);
  ASSERT_EQ(thesis.size(), 1u);
  EXPECT_EQ(thesis[0].robot, kRed2);
  EXPECT_NEAR(static_cast<double>(thesis[0].since_utime - at_s(kKickOffS)) * 1e-6, 2.0, 0.05);
}

TEST_F(WalkingInto, TheRobotBehindWalkingIntoTheOnesBackIsPenalised) {
  put_robot(kBlue2, 200.f, 1000.f, 0.f); // stands facing +x
  put_robot(kRed2, -300.f, 1000.f, 0.f); // walks up behind it and on into it at 100 mm/s
  start_playing();
  const auto given =
      play(kKickOffS, 5, [&](double t) { put_robot(kRed2, std::min(60.f, -300.f + 100.f * float(t)), 1000.f, 0.f); });
  ASSERT_EQ(given.size(), 1u);
  EXPECT_EQ(given[0].robot, kRed2);
}

TEST_F(WalkingInto, ABumpShorterThanTheMinimumContactIsNoFoul) {
  // Blue 2 walks into standing red 2 at 200 mm/s, in contact for 0.5 s, then backs off.
  put_robot(kRed2, 0.f, 0.f, 0.f);
  put_robot(kBlue2, 500.f, 0.f, kPi);
  start_playing();
  const auto bump = [&](double t) {
    const float x = t < 1.25 ? 500.f - 200.f * float(t) : 250.f + 200.f * float(t - 1.25);
    put_robot(kBlue2, x, 0.f, kPi);
  };
  EXPECT_TRUE(play(kKickOffS, 3, bump).empty());
  // With no minimum the same bump is a foul, the walker's.
  rules.pushing_min_contact_s = 0;
  referee.reset();
  put_robot(kBlue2, 500.f, 0.f, kPi);
  start_playing();
  const auto given = play(kKickOffS, 3, bump);
  ASSERT_EQ(given.size(), 1u);
  EXPECT_EQ(given[0].robot, kBlue2);
}

TEST_F(WalkingInto, TwoStandingRobotsInContactIsNoFoul) {
  put_robot(kRed2, 0.f, 1000.f, 0.f);
  put_robot(kBlue2, 200.f, 1000.f, 0.f); // the thesis would call red at once
  start_playing();
  EXPECT_TRUE(play(kKickOffS, 10, [](double) {}).empty());
}

TEST_F(WalkingInto, BackingAwayIsNoFoul) {
  // Blue 2 backs away from red 2 (which the thesis would call at once), and red 3 stands
  // while blue 3 turns on the spot beside it.
  put_robot(kRed2, 0.f, 1000.f, 0.f);
  put_robot(kBlue2, 150.f, 1000.f, 0.f);
  put_robot(kRed3, 0.f, -1000.f, 0.f);
  put_robot(kBlue3, 0.f, -750.f, 0.f);
  start_playing();
  const auto given = play(kKickOffS, 4, [&](double t) {
    put_robot(kBlue2, 150.f + 100.f * float(t), 1000.f, 0.f);
    put_robot(kBlue3, 0.f, -750.f, float(t));
  });
  EXPECT_TRUE(given.empty());
}

TEST_F(WalkingInto, APlacementIsNoWalk) {
  // Red 3 re-enters on the -y touchline (the ball is on the +y side), 310 mm from blue 2,
  // and creeps towards it at 30 mm/s: a slow step, not the 350 mm jump from its bench.
  rules.removal_s = 1;
  put_ball(-2500.f, 1500.f);
  put_robot(kRed3, -400.f, 0.f, 0.f);
  put_robot(kBlue2, -1200.f, -1690.f, -kPi / 2); // stands, facing red 3's re-entry spot
  start_playing();
  put_robot(kRed3, -2700.f, 0.f, 0.f); // an illegal defender: off for 1 s
  auto d = update_at(kKickOffS + 1);
  ASSERT_EQ(d.penalties.size(), 1u);
  apply(d);
  d = update_at(kKickOffS + 2);
  ASSERT_EQ(d.released.size(), 1u);
  expect_pose(d.placements[0].pose, -1200.f, -2000.f, kPi / 2);
  apply(d);
  const auto creep = [&](double t) { put_robot(kRed3, -1200.f, -2000.f + 30.f * float(t), kPi / 2); };
  EXPECT_TRUE(play(kKickOffS + 2, 1, creep).empty()); // in contact from 0.33 s on
}

TEST_F(WalkingInto, AStoppageEndsTheContactsTiming) {
  // Blue 2 walks into red 2 for the last 0.25 s of the first half and stands through the
  // break; in the second half it walks on: the contact is timed from the second half's
  // PLAYING (702 s), not from before the break.
  rules.game_stuck_s = 0;
  rules.manual_placement = false;
  put_robot(kRed2, -50.f, 1500.f, 0.f);
  put_robot(kBlue2, 400.f, 1500.f, kPi);
  start_playing();
  update_at(650);
  play(650, 1, [&](double t) { put_robot(kBlue2, 400.f - 200.f * float(t), 1500.f, kPi); }); // to 200 mm
  ASSERT_NE(ref().state(), GameState::kPlaying);
  for (double s : {660.0, 700.0, 701.9}) EXPECT_TRUE(update_at(s).penalties.empty());
  const auto given = play(701.9, 3, [&](double t) {
    put_robot(kBlue2, std::max(100.f, 200.f - 100.f * float(std::max(0.0, t - 0.1))), 1500.f, kPi);
  });
  ASSERT_EQ(given.size(), 1u);
  EXPECT_EQ(given[0].robot, kBlue2);
  EXPECT_GE(given[0].since_utime, at_s(702.95)); // a second into the second half
}

TEST_F(Pushing, ACrashedRobotIsNotPenalised) {
  put_robot(kRed2, 0.f, 1000.f, 0.f, /*active=*/false);
  start_playing();
  EXPECT_TRUE(update_at(60).penalties.empty());
}

TEST_F(RefereeTest, TeammatesBumpingIsNoFoul) {
  put_ball(500.f, 1500.f);
  put_robot(kRed2, -300.f, 1000.f, 0.f);
  put_robot(kRed3, -100.f, 1000.f, 0.f);
  start_playing();
  EXPECT_TRUE(update_at(60).penalties.empty());
}

TEST_F(RefereeTest, ContestingTheBallIsNoFoulAndStopsTheRobotFartherFromIt) {
  put_ball(-20.f, 0.f); // 80 mm from red 2, 120 mm from blue 2
  put_robot(kRed2, -100.f, 0.f, 0.f);
  put_robot(kBlue2, 100.f, 0.f, kPi);
  start_playing();
  const auto d = update_at(60);
  EXPECT_TRUE(d.penalties.empty());
  ASSERT_EQ(d.stopped.size(), 1u);
  EXPECT_EQ(d.stopped[0].robot, kBlue2);
  EXPECT_EQ(d.stopped[0].winner, kRed2);
}

TEST_F(RefereeTest, TeammatesDoNotContestTheBall) {
  put_ball(-20.f, 0.f); // as above, but both robots are red: their feet collide, neither is held
  put_robot(kRed2, -100.f, 0.f, 0.f);
  put_robot(kRed3, 100.f, 0.f, kPi);
  start_playing();
  const auto d = update_at(60);
  EXPECT_TRUE(d.penalties.empty());
  EXPECT_TRUE(d.stopped.empty());
}

TEST_F(RefereeTest, FacingEachOtherAwayFromTheBallTheSquarerWalkerPushes) {
  rules.pushing_model = "thesis";
  put_ball(-2500.f, -1500.f);
  put_robot(kRed2, -100.f, 0.f, 0.f);           // walks straight at blue 2
  put_robot(kBlue2, 100.f, 0.f, kPi - 0.5f);    // 0.5 rad off red 2
  start_playing();
  const auto d = update_at(60);
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].robot, kRed2);
  EXPECT_TRUE(d.stopped.empty());
}

TEST_F(RefereeTest, RobotsReleasedTogetherDoNotLandOnEachOther) {
  rules.pushing_model = "thesis";
  put_ball(500.f, 1500.f);
  put_robot(kRed2, 0.f, 1000.f, 0.f);
  put_robot(kBlue2, 200.f, 1000.f, 0.f);
  put_robot(kRed3, 0.f, -500.f, 0.f);
  put_robot(kBlue3, 200.f, -500.f, 0.f);
  start_playing();
  auto d = update_at(60);
  ASSERT_EQ(d.penalties.size(), 2u);
  apply(d);
  d = update_at(90);
  ASSERT_EQ(d.placements.size(), 2u);
  EXPECT_EQ(d.placements[0].robot, kRed2);
  expect_pose(d.placements[0].pose, -1200.f, -2000.f, kPi / 2);
  EXPECT_EQ(d.placements[1].robot, kRed3);
  expect_pose(d.placements[1].pose, -800.f, -2000.f, kPi / 2); // one 400 mm step towards the centre
}

TEST_F(Pushing, ReEntrySpotTakenMovesAlongTheTouchline) {
  update_at(0);
  apply(update_at(60));
  put_robot(kRed3, -1200.f, -2000.f, kPi / 2); // standing on the spot
  put_robot(kRed4, -800.f, -1950.f, kPi / 2);  // and on the next one towards the centre
  const auto d = update_at(90);
  ASSERT_EQ(d.placements.size(), 1u);
  expect_pose(d.placements[0].pose, -1600.f, -2000.f, kPi / 2); // then towards the own goal
}

TEST_F(RefereeTest, HalfTimeEndsEveryPenalty) {
  rules.game_stuck_s = 0; // whole halves without a touch: the clock alone
  start_playing();
  put_robot(kRed3, -2800.f, 0.f, 0.f); // illegal defender at 640 s, until 670 s
  apply(update_at(640));
  ASSERT_TRUE(ref().penalised(kRed3));
  const auto d = update_at(651);
  ASSERT_EQ(d.released.size(), 1u);
  EXPECT_EQ(d.released[0], kRed3);
  ASSERT_EQ(d.placements.size(), 1u);
  // Ball to the centre spot: equally far from both touchlines, the own (-y) one wins.
  expect_pose(d.placements[0].pose, -1200.f, -2000.f, kPi / 2);
  EXPECT_FALSE(ref().penalised(kRed3));
}

// --- illegal defender ------------------------------------------------------------------

TEST_F(RefereeTest, FieldPlayerInItsOwnGoalBoxIsAnIllegalDefender) {
  put_ball(0.f, 0.f);
  put_robot(kRed3, -2800.f, 0.f, 0.f);    // 200 mm in front of its goal line
  put_robot(kBlue3, 2800.f, 500.f, kPi);  // the same in the other box
  start_playing();
  const auto d = update_at(60);
  ASSERT_EQ(d.penalties.size(), 2u);
  EXPECT_EQ(d.penalties[0].robot, kRed3);
  EXPECT_EQ(d.penalties[0].kind, PenaltyKind::kIllegalDefender);
  EXPECT_EQ(d.penalties[1].robot, kBlue3);
  EXPECT_EQ(d.penalties[1].kind, PenaltyKind::kIllegalDefender);
}

TEST_F(RefereeTest, TheGoalieMayStandInItsGoalBoxAndAttackersInTheOpponents) {
  put_ball(0.f, 0.f);
  put_robot(kRedGoalie, -2800.f, 0.f, 0.f);
  put_robot(kBlue3, -2800.f, 800.f, kPi); // an attacker in red's box
  start_playing();
  EXPECT_TRUE(update_at(60).penalties.empty());
}

TEST_F(RefereeTest, GoalBoxEdgeCountsAsInside) {
  put_ball(0.f, 0.f);
  put_robot(kRed3, -2400.f, 1100.f, 0.f); // the box's front corner
  put_robot(kRed4, -2399.f, 0.f, 0.f);    // 1 mm outside
  start_playing();
  const auto d = update_at(60);
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].robot, kRed3);
}

TEST_F(RefereeTest, NoIllegalDefenderOutsidePlaying) {
  put_robot(kRed3, -2800.f, 0.f, 0.f);
  update_at(0);
  EXPECT_TRUE(update_at(10).penalties.empty()); // READY
  rules.illegal_defender = false;
  referee.reset();
  start_playing();
  EXPECT_TRUE(update_at(60).penalties.empty()); // switched off
}

// --- leaving the field -----------------------------------------------------------------

TEST_F(RefereeTest, LeavingTheFieldByMoreThanTheMarginIsPenalised) {
  put_ball(0.f, 0.f);
  put_robot(kRed3, 0.f, 2200.f, kPi / 2);        // 200 mm past the touchline: the margin
  put_robot(kRed4, -1000.f, 2200.5f, kPi / 2);   // just beyond it
  put_robot(kBlue3, 3250.f, 1500.f, 0.f);        // 250 mm past the goal line
  start_playing();
  const auto d = update_at(60);
  ASSERT_EQ(d.penalties.size(), 2u);
  EXPECT_EQ(d.penalties[0].robot, kRed4);
  EXPECT_EQ(d.penalties[0].kind, PenaltyKind::kLeavingField);
  EXPECT_EQ(d.penalties[1].robot, kBlue3);
  EXPECT_EQ(d.penalties[1].kind, PenaltyKind::kLeavingField);
  EXPECT_EQ(d.placements.size(), 2u);
}

TEST_F(RefereeTest, LeavingTheFieldCountsInReadyButNotInInitial) {
  rules.removal_s = 100; // still serving at SET
  put_robot(kRed3, 0.f, -2300.f, -kPi / 2);
  EXPECT_TRUE(update_at(0).penalties.empty()); // INITIAL
  EXPECT_TRUE(update_at(0.5).penalties.empty());
  const auto d = update_at(10); // READY
  ASSERT_EQ(d.penalties.size(), 1u);
  EXPECT_EQ(d.penalties[0].kind, PenaltyKind::kLeavingField);
  apply(d);
  // Still on the bench at SET: not put on a kick-off position.
  EXPECT_TRUE(update_at(46).placements.empty());
  EXPECT_EQ(ref().state(), GameState::kSet);
}

TEST_F(RefereeTest, CrashedRobotsAndSwitchedOffRuleGiveNoLeavingPenalty) {
  put_robot(kRed3, 0.f, -2300.f, -kPi / 2, /*active=*/false);
  update_at(0);
  EXPECT_TRUE(update_at(10).penalties.empty());
  rules.leaving_field = false;
  referee.reset();
  put_robot(kRed3, 0.f, -2300.f, -kPi / 2);
  update_at(0);
  EXPECT_TRUE(update_at(10).penalties.empty());
}

} // namespace
} // namespace touchline::sim
