// Search (issue #17: no turning on the spot for long when the ball is lost): the team ball,
// the search cycle of turns and walks to search spots, a ball put back where the rules put
// it; the same hand-worked cases as tests/behaviour_py/test_search.py.
#include "touchline/behaviour/skills/search.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "boards.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/team.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::teamBoard;

namespace {

using AT = ActionCommand::ActionType;
constexpr int64_t NOW = 10000000;

/// Teammate `number`'s message: it sees the ball at (x, y) from `distance` mm
/// (NO_BALL_DISTANCE: it does not).
TeamMessage sighting(int number, int distance, int x, int y, bool penalised = false, int64_t age = 0) {
  const TeamInfo info{number, ROLE_DEFENDER, distance != NO_BALL_DISTANCE, penalised, false, distance, x, y};
  return {number, NOW - age, encodeMessage(info)};
}

void expectBall(const std::optional<FieldPoint>& ball, float x, float y) {
  ASSERT_TRUE(ball.has_value());
  EXPECT_EQ(ball->x, x);
  EXPECT_EQ(ball->y, y);
}

void expectPose(const AbsCoord& p, float x, float y, float theta) {
  EXPECT_NEAR(p.x, x, 1e-3f);
  EXPECT_NEAR(p.y, y, 1e-3f);
  EXPECT_NEAR(p.theta, theta, 1e-5f);
}

/// A robot at pos that last saw the ball at (ballX, ballY) SEARCH_TURN_FRAMES + lost frames ago.
Blackboard lostBoard(AbsCoord pos, float ballX, float ballY, int lost, std::vector<TeamMessage> messages = {}) {
  return teamBoard(pos, ballX, ballY, false, SEARCH_TURN_FRAMES + lost, GameState::PLAYING, 2, false, false,
                   std::move(messages), NOW);
}

/// A robot at pos that last saw the ball at (ballX, ballY) `lost` frames ago, told of a drop-in
/// (dropInTeam, dropInTime); lost 0: it sees the ball there.
Blackboard dropInBoard(AbsCoord pos, float ballX, float ballY, int lost, int dropInTeam, int dropInTime) {
  Blackboard board = teamBoard(pos, ballX, ballY, lost == 0, lost);
  board.gameController.dropInTeam = dropInTeam;
  board.gameController.dropInTime = dropInTime;
  return board;
}

void expectSpot(FieldPoint spot, float x, float y) {
  EXPECT_EQ(spot.x, x);
  EXPECT_EQ(spot.y, y);
}

} // namespace

TEST(Search, TheTeamBallIsTheNearestFreshSighting) {
  EXPECT_FALSE(teamBall(2, {}, NOW).has_value());
  expectBall(teamBall(2, {sighting(3, 900, 100, 200), sighting(4, 700, -500, 300)}, NOW), -500.f, 300.f);
  expectBall(teamBall(2, {sighting(4, 700, -500, 300), sighting(3, 700, 100, 200)}, NOW), 100.f, 200.f); // tie: lower
  expectBall(teamBall(2, {sighting(3, 900, 100, 200), sighting(4, NO_BALL_DISTANCE, -500, 300)}, NOW), 100.f, 200.f);
}

TEST(Search, StalePenalisedAndOwnSightingsDoNotCount) {
  EXPECT_FALSE(teamBall(2, {sighting(3, 900, 100, 200, false, MESSAGE_STALE_US + 1)}, NOW).has_value());
  expectBall(teamBall(2, {sighting(3, 900, 100, 200, false, MESSAGE_STALE_US)}, NOW), 100.f, 200.f);
  EXPECT_FALSE(teamBall(2, {sighting(3, 900, 100, 200, true)}, NOW).has_value());
  EXPECT_FALSE(teamBall(2, {sighting(2, 900, 100, 200)}, NOW).has_value());
}

TEST(Search, TheRolesStandForTheTeamBallAsForTheirOwn) {
  expectPose(teamBallTarget(ROLE_STRIKER, 1000.f, 0.f, 0.f, thesisSupporters()), 800.f, 0.f, 0.f);
  expectPose(teamBallTarget(ROLE_DEFENDER, 0.f, 600.f, 0.f, thesisSupporters()), -1250.f, 350.f, std::atan2(250.f, 1250.f));
  expectPose(teamBallTarget(ROLE_MIDFIELDER, 2100.f, 0.f, 100.f, thesisSupporters()), 2200.f, 500.f, std::atan2(-500.f, -100.f));
}

TEST(Search, ForATeamBallOnATouchlineTheStrikerStandsWhereGoToBallWould) {
  // Facing the goal it would stand 120 mm beyond the line, where no walk takes it; kickAim
  // turns it along the line, FIELD_EDGE_SLACK out, as GoToBall does for its own ball.
  const float ballX = 1000.f, ballY = FIELD_HALF_WIDTH;
  const FieldPointExact aim = kickAim(ballX, ballY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, BEHIND_BALL_DIST);
  const AbsCoord expected = pointBehindBall(AbsCoord{ballX, ballY, 0.f}, static_cast<float>(aim.x),
                                            static_cast<float>(aim.y), BEHIND_BALL_DIST);
  const AbsCoord target = teamBallTarget(ROLE_STRIKER, ballX, ballY, 0.f, thesisSupporters());
  EXPECT_EQ(target.x, expected.x);
  EXPECT_EQ(target.y, expected.y);
  EXPECT_EQ(target.theta, expected.theta);
  EXPECT_NEAR(target.y, FIELD_HALF_WIDTH + FIELD_EDGE_SLACK, 1e-2f);
}

TEST(Search, ALostRobotWalksToTheTeamBallInsteadOfTurning) {
  // Own ball last seen on the right: alone it would turn right; the teammate sees it ahead-left.
  auto body = Search().tick(lostBoard({0.f, 0.f, 0.f}, 0.f, -1000.f, 1, {sighting(3, 600, 1000, 1000)}), ROLE_STRIKER);
  ASSERT_TRUE(body.has_value());
  EXPECT_EQ(body->actionType, AT::WALK);
  EXPECT_GT(body->turn, 0.f); // turning to face the team ball's spot, then walking
  body = Search().tick(lostBoard({0.f, 0.f, 0.f}, 1000.f, 0.f, 1, {sighting(3, 600, 2000, 0)}), ROLE_STRIKER);
  ASSERT_TRUE(body.has_value());
  EXPECT_EQ(body->actionType, AT::WALK);
  EXPECT_GT(body->forward, 0.f);
  EXPECT_NEAR(body->turn, 0.f, 1e-6f);
  // Not lost for long enough: the role's own skill plays.
  EXPECT_FALSE(Search().tick(lostBoard({0.f, 0.f, 0.f}, 1000.f, 0.f, 0, {sighting(3, 600, 2000, 0)}), ROLE_STRIKER));
}

TEST(Search, ARobotThatLostTheBallAtItsFeetStepsAwayFromItBeforeTurning) {
  // A full match had a striker stand on a ball in a corner and turn on it for 10 s: there no
  // head turn sees it. Last seen 100 mm ahead-left: it steps back-right, not turning, ...
  auto body = Search().tick(lostBoard({0.f, 0.f, 0.f}, 60.f, 80.f, 1, {sighting(3, 600, 1000, 1000)}), ROLE_STRIKER);
  ASSERT_TRUE(body.has_value());
  EXPECT_EQ(body->actionType, AT::WALK);
  EXPECT_NEAR(body->turn, 0.f, 1e-6f);
  EXPECT_NEAR(std::atan2(body->left, body->forward), std::atan2(-80.f, -60.f), 1e-5f);
  // ... and behind it, forwards; beside a line, not over it.
  body = Search().tick(lostBoard({0.f, 0.f, 0.f}, -100.f, 0.f, 1), ROLE_MIDFIELDER);
  ASSERT_TRUE(body.has_value());
  EXPECT_GT(body->forward, 0.f);
  EXPECT_NEAR(body->left, 0.f, 1e-3f);
  EXPECT_NEAR(body->turn, 0.f, 1e-6f);
  body = Search().tick(lostBoard({0.f, -FIELD_HALF_WIDTH, kPi / 2}, 0.f, -FIELD_HALF_WIDTH + 100.f, 1), ROLE_STRIKER);
  ASSERT_TRUE(body.has_value());
  EXPECT_NEAR(body->forward, 0.f, 1e-3f);
  // Once it would be BALL_AT_FEET_DIST away, the search turns as before.
  body = Search().tick(lostBoard({0.f, 0.f, 0.f}, 0.f, BALL_AT_FEET_DIST, 1), ROLE_STRIKER);
  ASSERT_TRUE(body.has_value());
  EXPECT_NEAR(body->turn, SEARCH_TURN_SPEED, 1e-6f);
  EXPECT_EQ(body->forward, 0.f);
}

TEST(Search, SearchSpotsCycleRoundTheCentreCircleFromEachRolesOwn) {
  const FieldPoint expected[] = {{1500.f, 0.f}, {0.f, 1200.f}, {-1500.f, 0.f}, {0.f, -1200.f}, {1500.f, 0.f}};
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(searchSpot(ROLE_STRIKER, k).x, expected[k].x);
    EXPECT_EQ(searchSpot(ROLE_STRIKER, k).y, expected[k].y);
  }
  EXPECT_EQ(searchSpot(ROLE_MIDFIELDER, 0).y, 1200.f);
  EXPECT_EQ(searchSpot(ROLE_DEFENDER, 0).x, -1500.f);
}

TEST(Search, TheStrikerTurnsBrieflyThenWalksToASearchSpot) {
  const auto body = [](int lost, AbsCoord pos = {0.f, 0.f, 0.f}) {
    const auto b = Search().tick(lostBoard(pos, 0.f, -1000.f, lost), ROLE_STRIKER);
    EXPECT_TRUE(b.has_value());
    return b.value_or(ActionCommand::Body{});
  };
  EXPECT_NEAR(body(1).turn, -SEARCH_TURN_SPEED, 1e-6f); // towards the side it was last seen on
  EXPECT_NEAR(body(SEARCH_TURN_LIMIT_FRAMES).turn, -SEARCH_TURN_SPEED, 1e-6f);
  EXPECT_LT(SEARCH_TURN_LIMIT_FRAMES / 30.f * SEARCH_TURN_SPEED, 2 * kPi); // never a full turn on the spot
  auto walk = body(SEARCH_TURN_LIMIT_FRAMES + 1); // to (1500, 0), straight ahead
  EXPECT_EQ(walk.actionType, AT::WALK);
  EXPECT_GT(walk.forward, 0.f);
  EXPECT_NEAR(walk.turn, 0.f, 1e-6f);
  EXPECT_NEAR(body(SEARCH_CYCLE_FRAMES + 1).turn, -SEARCH_TURN_SPEED, 1e-6f); // the next cycle's turn ...
  walk = body(SEARCH_CYCLE_FRAMES + SEARCH_TURN_LIMIT_FRAMES + 1, {1500.f, 0.f, 0.f}); // ... then to (0, 1200)
  // behind-left, the spot faces +x: backwards and left, faster than turning round and back
  EXPECT_EQ(walk.actionType, AT::WALK);
  EXPECT_LT(walk.forward, 0.f);
  EXPECT_GT(walk.left, 0.f);
  EXPECT_NEAR(walk.turn, 0.f, 1e-6f);
}

TEST(Search, ASupporterGoesHomeFirstThenSearchesFromSpotToSpot) {
  const auto body = [](int lost, AbsCoord pos) {
    return Search().tick(lostBoard(pos, 0.f, 1500.f, lost), ROLE_MIDFIELDER);
  };
  EXPECT_FALSE(body(1, {0.f, 0.f, 0.f})); // away from home (0, 800): the thesis walks home
  const auto turn = body(1, {0.f, 800.f - HOME_NEAR_DIST + 1.f, 0.f}); // home: turns
  ASSERT_TRUE(turn);
  EXPECT_NEAR(turn->turn, SEARCH_TURN_SPEED, 1e-6f);
  EXPECT_FALSE(body(SEARCH_TURN_LIMIT_FRAMES + 1, {0.f, 800.f, 0.f})); // then the thesis stands at home
  const auto anywhere = body(SEARCH_CYCLE_FRAMES + 1, {0.f, 0.f, 0.f}); // turns anywhere
  ASSERT_TRUE(anywhere);
  EXPECT_NEAR(anywhere->turn, SEARCH_TURN_SPEED, 1e-6f);
  const auto walk = body(SEARCH_CYCLE_FRAMES + SEARCH_TURN_LIMIT_FRAMES + 1, {0.f, 800.f, 0.f}); // to (0, 1200)
  ASSERT_TRUE(walk);
  EXPECT_EQ(walk->actionType, AT::WALK);
  EXPECT_GT(walk->left, 0.f); // sideways, facing +x
  EXPECT_NEAR(walk->turn, 0.f, 1e-6f);
}

TEST(Search, TheTeamSearchesButTheGoalieKeepsItsBox) {
  Team striker(ROLE_STRIKER);
  EXPECT_NEAR(striker.tick(lostBoard({0.f, 0.f, 0.f}, 0.f, -1000.f, 1)).body.turn, -SEARCH_TURN_SPEED, 1e-6f);
  Team goalie;
  Blackboard board = lostBoard({-2700.f, 0.f, 0.f}, 0.f, -1000.f, 1);
  board.gameController.playerNumber = 1; // the goalie at home: stands
  EXPECT_EQ(goalie.tick(board).body.actionType, AT::STAND);
}

TEST(Search, ABallPutBackLiesOnTheThrowInLineWhereTheSpl2011RulesPutIt) {
  const float lineY = FIELD_HALF_WIDTH - THROW_IN_LINE_INSET, lineEndX = FIELD_HALF_LENGTH - THROW_IN_LINE_END;
  // Over the touchline (it lies farther beyond it than beyond the goal line), by us: towards
  // our goal (-x); by them: towards theirs; not known: where it crossed.
  expectSpot(dropInSpot(500.f, FIELD_HALF_WIDTH + 80.f, 0, 0), 500.f - DROP_IN_SETBACK, lineY);
  expectSpot(dropInSpot(500.f, -FIELD_HALF_WIDTH - 80.f, 1, 0), 500.f + DROP_IN_SETBACK, -lineY);
  expectSpot(dropInSpot(500.f, FIELD_HALF_WIDTH - 30.f, -1, 0), 500.f, lineY); // last seen just inside
  expectSpot(dropInSpot(500.f, FIELD_HALF_WIDTH + 80.f, 1, 1), 500.f - DROP_IN_SETBACK, lineY); // team 1's "us"
  // The setback stops at the throw-in line's end.
  expectSpot(dropInSpot(FIELD_HALF_LENGTH - 200.f, FIELD_HALF_WIDTH + 300.f, 1, 0), lineEndX, lineY);
  // Over a goal line by its attackers (we attack +x): to the halfway line, on its side's line; ...
  expectSpot(dropInSpot(FIELD_HALF_LENGTH + 100.f, 700.f, 0, 0), 0.f, lineY);
  expectSpot(dropInSpot(-FIELD_HALF_LENGTH - 100.f, -2100.f, 1, 0), 0.f, -lineY);
  // ... by its defenders, or not known: to the line's end by that goal line.
  expectSpot(dropInSpot(FIELD_HALF_LENGTH + 100.f, 700.f, 1, 0), lineEndX, lineY);
  expectSpot(dropInSpot(-FIELD_HALF_LENGTH - 100.f, -300.f, 0, 0), -lineEndX, -lineY);
  expectSpot(dropInSpot(FIELD_HALF_LENGTH + 100.f, -700.f, -1, 0), lineEndX, -lineY);
}

TEST(Search, ARobotThatDidNotSeeTheBallPutBackWalksAndLooksToWhereTheRulesPutIt) {
  // Last seen rolling over the left touchline at x = 500; we put it out: it lies at x = -500,
  // behind the robot, which faces where the ball left.
  const AbsCoord pos{300.f, 1700.f, 0.5f};
  const auto out = [&](int dropInTeam, int dropInTime, AbsCoord at) {
    return dropInBoard(at, 500.f, FIELD_HALF_WIDTH + 50.f, 10, dropInTeam, dropInTime);
  };
  Search search;
  EXPECT_FALSE(search.tick(out(-1, -1, pos), ROLE_MIDFIELDER)); // no drop-in yet
  const auto body = search.tick(out(0, 0, pos), ROLE_MIDFIELDER);
  ASSERT_TRUE(search.dropIn());
  expectSpot(*search.dropIn(), 500.f - DROP_IN_SETBACK, FIELD_HALF_WIDTH - THROW_IN_LINE_INSET);
  ASSERT_TRUE(body);
  EXPECT_EQ(body->actionType, AT::WALK);
  EXPECT_GT(body->turn, 0.f); // turning round to it
  // It keeps the spot while the drop-in is young and the ball unseen, ...
  EXPECT_TRUE(search.tick(out(0, DROP_IN_FRESH_S - 1, pos), ROLE_MIDFIELDER));
  EXPECT_TRUE(search.dropIn());
  // ... and forgets it once it sees the ball (the role's own skill plays), or when it is old.
  EXPECT_FALSE(search.tick(dropInBoard(pos, -500.f, FIELD_HALF_WIDTH, 0, 0, 1), ROLE_MIDFIELDER));
  EXPECT_FALSE(search.dropIn());
  Search aged;
  aged.tick(out(0, 0, pos), ROLE_MIDFIELDER);
  EXPECT_FALSE(aged.tick(out(0, DROP_IN_FRESH_S, pos), ROLE_MIDFIELDER));
  EXPECT_FALSE(aged.dropIn());
  // The Team looks there too: the spot is behind-left, and so is the head.
  const AbsCoord turned{-200.f, 1300.f, 0.6f};
  const auto head = Team(ROLE_STRIKER).tick(out(0, 0, turned)).head;
  const RRCoord spot = toRobotRelative(turned, 500.f - DROP_IN_SETBACK, FIELD_HALF_WIDTH - THROW_IN_LINE_INSET);
  EXPECT_NEAR(head.yaw, spot.heading, 1e-5f);
  EXPECT_GT(head.yaw, 1.5f);
}

TEST(Search, ARobotThatSeesTheBallPutBackOrAnotherDropInPlaysOn) {
  // It saw the ball as it was put back: its own skill plays the real ball.
  Search search;
  EXPECT_FALSE(search.tick(dropInBoard({}, -500.f, FIELD_HALF_WIDTH, 0, 0, 0), ROLE_STRIKER));
  EXPECT_FALSE(search.dropIn());
  // The same drop-in told again (dropInTime not started again) keeps the spot latched from the
  // sighting before it, wherever the ball estimate goes since.
  Search latched;
  latched.tick(dropInBoard({}, 1000.f, 0.f, 10, 1, 3), ROLE_STRIKER);
  EXPECT_TRUE(latched.dropIn());
  latched.tick(dropInBoard({}, 0.f, 0.f, 10, 1, 3), ROLE_STRIKER);
  ASSERT_TRUE(latched.dropIn()); // the one it latched, kept
  const FieldPoint first = dropInSpot(1000.f, 0.f, 1, 0);
  expectSpot(*latched.dropIn(), first.x, first.y);
}
