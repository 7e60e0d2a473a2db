// The team behaviour: thesis Algorithms 4.1 and 4.2, the goal box, the shooting path, the
// goalie, the striker, team messages and roles, game states; the same hand-worked cases as
// tests/behaviour_py/test_team.py.
#include "touchline/behaviour/skills/team.hpp"

#include <gtest/gtest.h>

#include "boards.hpp"
#include "touchline/behaviour/skills/line_up_and_kick.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::board;
using touchline::behaviour::test::seenRobot;
using touchline::behaviour::test::teamBoard;

namespace {

using AT = ActionCommand::ActionType;

void expectPoint(const FieldPoint& p, float x, float y, float tolerance = 1e-3f) {
  EXPECT_NEAR(p.x, x, tolerance);
  EXPECT_NEAR(p.y, y, tolerance);
}

} // namespace

// Algorithm 4.1: the midfielder's position from the ball's x (thesis numbers).
TEST(TeamMidfielder, BallBeyond2000GoesTo2200_0) {
  expectPoint(midfielderTarget(2500.f, 300.f, 500.f, thesisSupporters()), 2200.f, 0.f);
  expectPoint(supporterTarget(2200.f, 0.f, 2500.f, 300.f, 500.f), 2200.f, 0.f); // behind the ball
}

TEST(TeamMidfielder, BallBetween1200And2000Stands1200BesideIt) {
  expectPoint(midfielderTarget(1500.f, 200.f, -500.f, thesisSupporters()), 1500.f, -1000.f);
  expectPoint(midfielderTarget(1500.f, 200.f, 800.f, thesisSupporters()), 1500.f, 1400.f);
}

TEST(TeamMidfielder, BallOnOwnGoalLineIs2500InFrontOfIt) {
  expectPoint(midfielderTarget(-3000.f, 0.f, 1000.f, thesisSupporters()), -500.f, 1000.f);
  expectPoint(midfielderTarget(1200.f - 4200.f / 2, 0.f, 1000.f, thesisSupporters()), -900.f + 1250.f, 1000.f);
}

// Algorithm 4.2: the defender's position from the ball's x (thesis numbers), y blocking the
// ball-own-goal line.
TEST(TeamDefender, BallBelowMinus800GoesToMinus1800_0) { expectPoint(defenderTarget(-1000.f, 400.f, thesisSupporters()), -1800.f, 0.f); }

TEST(TeamDefender, BallAt0Is1250BehindItOnTheGoalLine) { expectPoint(defenderTarget(0.f, 600.f, thesisSupporters()), -1250.f, 350.f); }

TEST(TeamDefender, BallBeyond1250StopsAtMinus1200) { expectPoint(defenderTarget(1500.f, -900.f, thesisSupporters()), -1200.f, -360.f); }

TEST(TeamSupporter, GoalBoxClamp) {
  expectPoint(clampOutOfOwnBox(-2700.f, 300.f), -2200.f, 300.f);
  expectPoint(clampOutOfOwnBox(-2300.f, -1200.f), -2200.f, -1200.f);
  expectPoint(clampOutOfOwnBox(-2700.f, 1400.f), -2700.f, 1400.f);
  expectPoint(clampOutOfOwnBox(-2000.f, 0.f), -2000.f, 0.f);
  expectPoint(supporterTarget(-2900.f, 1000.f, -2950.f, -1500.f, 1000.f), -2200.f, 1000.f);
}

TEST(TeamSupporter, ShootingPathAvoidanceInFrontOfTheBall) {
  // Midfielder at its far spot with the ball straight behind it: sideways to its own side.
  expectPoint(supporterTarget(2200.f, 0.f, 2100.f, 0.f, 100.f), 2200.f, 500.f);
  expectPoint(supporterTarget(2200.f, 0.f, 2100.f, 0.f, -100.f), 2200.f, -500.f);
  // Defender in front of a deep ball: off the line from (-2500, 100) to (3000, 0).
  expectPoint(supporterTarget(-1800.f, 0.f, -2500.f, 100.f, -300.f), -1800.f, -412.7273f);
  // Already clear of the line, or behind the ball: unchanged.
  expectPoint(supporterTarget(-500.f, 1000.f, -3000.f, 0.f, 1000.f), -500.f, 1000.f);
  expectPoint(supporterTarget(-1250.f, 0.f, 0.f, 0.f, 0.f), -1250.f, 0.f);
}

TEST(TeamSupporter, FaceTheBallAndGoHomeWhenItIsLost) {
  EXPECT_EQ(Defender(thesisSupporters()).tick(board({-1250.f, 0.f, 0.f}, 0.f, 0.f)).body.actionType, AT::STAND);
  // Ball lost for long: the midfielder walks home to (0, 800), to its left: sideways, as it ends facing +x.
  const auto command = Midfielder().tick(board({0.f, 0.f, 0.f}, 1000.f, 0.f, false, 91));
  EXPECT_EQ(command.body.actionType, AT::WALK);
  EXPECT_NEAR(command.body.left, 200.f, 1e-3f);
  EXPECT_NEAR(command.body.turn, 0.f, 1e-5f);
  EXPECT_EQ(Midfielder().tick(board({0.f, 800.f, 0.f}, 1000.f, 0.f, false, 91)).body.actionType, AT::STAND);
}

// Goalie
TEST(TeamGoalie, TargetOnTheGoalBallLine) {
  expectPoint(goalieTarget(0.f, 0.f), -2600.f, 0.f);
  expectPoint(goalieTarget(-2000.f, 1000.f), -2717.157f, 282.843f);
  expectPoint(goalieTarget(-2990.f, 1900.f), -2900.f, 399.9945f);
}

TEST(TeamGoalie, StaysInItsBox) {
  for (int ballX = -3000; ballX <= 3000; ballX += 500) {
    for (int ballY = -2000; ballY <= 2000; ballY += 500) {
      const FieldPoint p = goalieTarget(static_cast<float>(ballX), static_cast<float>(ballY));
      EXPECT_TRUE(p.x >= -3000.f && p.x <= -2400.f && std::fabs(p.y) <= 1100.f) << ballX << ", " << ballY;
    }
  }
}

TEST(TeamGoalie, GuardsThenClearsABallNearItsBox) {
  Goalie goalie;
  EXPECT_EQ(goalie.tick(board({-2600.f, 0.f, 0.f}, 1000.f, 0.f)).body.actionType, AT::STAND);
  EXPECT_FALSE(goalie.clearing());
  goalie.tick(board({-2600.f, 0.f, 0.f}, -2200.f, 0.f));
  EXPECT_TRUE(goalie.clearing());
  goalie.tick(board({-2600.f, 0.f, 0.f}, -1900.f, 0.f)); // still within the leave margin
  EXPECT_TRUE(goalie.clearing());
  goalie.tick(board({-2600.f, 0.f, 0.f}, -1700.f, 0.f));
  EXPECT_FALSE(goalie.clearing());
  const auto lined = Goalie().tick(board({-2600.f, 0.f, 0.f}, -2470.f, 50.f)).body; // lined up: carry it out
  EXPECT_EQ(lined.actionType, AT::WALK);
  EXPECT_EQ(lined.forward, CARRY_SPEED);
}

// Striker
TEST(TeamStriker, CarriesTheBallPastARobotAheadTooAndIntoTheGoal) {
  auto body = Striker().tick(board({0.f, 0.f, 0.f}, 130.f, 50.f)).body;
  EXPECT_EQ(body.actionType, AT::WALK);
  EXPECT_EQ(body.forward, CARRY_SPEED);
  Blackboard ahead = board({0.f, 0.f, 0.f}, 130.f, 50.f);
  ahead.vision.robots = {seenRobot(550.f, 150.f)};
  body = Striker().tick(ahead).body;
  EXPECT_EQ(body.actionType, AT::WALK);
  EXPECT_EQ(body.forward, CARRY_SPEED);
  body = Striker().tick(board({2300.f, 0.f, 0.f}, 2430.f, 50.f)).body; // 570 mm from the goal's centre
  EXPECT_EQ(body.actionType, AT::WALK);
  EXPECT_EQ(body.forward, CARRY_SPEED);
}

// Team messages: the same bytes as the Python for the same inputs.
namespace {
const std::vector<uint8_t> VECTOR_1 = {0x02, 0x03, 0x02, 0x01, 0xD3, 0x04, 0x24,
                                       0xFA, 0xD1, 0x07, 0x2E, 0xFB, 0x38, 0x02};
const std::vector<uint8_t> VECTOR_2 = {0x02, 0x07, 0x03, 0x06, 0xFF, 0xFF, 0xFF,
                                       0x7F, 0x00, 0x80, 0xFF, 0x7F, 0x00, 0x80};
} // namespace

TEST(TeamMessage, TestVectors) {
  EXPECT_EQ(encodeMessage(makeTeamInfo(3, ROLE_STRIKER, true, false, false, 1234.75f, -1500.25f, 2000.5f, -1234.5f,
                                       567.5f)),
            VECTOR_1);
  EXPECT_EQ(decodeMessage(VECTOR_1), (TeamInfo{3, ROLE_STRIKER, true, false, false, 1235, -1500, 2001, -1234, 568}));
  EXPECT_EQ(encodeMessage(makeTeamInfo(7, ROLE_DEFENDER, false, true, true, 999.f, 40000.f, -40000.f, 50000.f,
                                       -50000.f)),
            VECTOR_2);
  EXPECT_EQ(decodeMessage(VECTOR_2),
            (TeamInfo{7, ROLE_DEFENDER, false, true, true, NO_BALL_DISTANCE, 32767, -32768, 32767, -32768}));
}

TEST(TeamMessage, RoundTripAndRejects) {
  const TeamInfo info{4, ROLE_MIDFIELDER, true, false, true, 65534, -32768, 12, 2999, -1999};
  EXPECT_EQ(decodeMessage(encodeMessage(info)), info);
  EXPECT_FALSE(decodeMessage(std::vector<uint8_t>(VECTOR_1.begin(), VECTOR_1.end() - 1)));
  std::vector<uint8_t> wrongVersion = VECTOR_1;
  wrongVersion[0] = 1; // the version before robot poses
  EXPECT_FALSE(decodeMessage(wrongVersion));
}

// Role assignment
namespace {
constexpr int64_t NOW = 10000000;

TeamMessage msg(int number, int distance, int role = ROLE_DEFENDER, bool penalised = false, int64_t age = 0) {
  const TeamInfo info{number, role, distance != NO_BALL_DISTANCE, penalised, false, distance, 0, 0};
  return {number, NOW - age, encodeMessage(info)};
}
} // namespace

TEST(TeamRoles, ClosestFieldPlayerIsStrikerOthersByNumber) {
  const std::vector<TeamMessage> messages = {msg(1, 0, ROLE_GOALIE), msg(3, 800), msg(4, 1500)};
  EXPECT_EQ(assignRole(2, 1200, ROLE_DEFENDER, messages, NOW), ROLE_DEFENDER);
  EXPECT_EQ(assignRole(4, 1500, ROLE_DEFENDER, {msg(2, 1200), msg(3, 800)}, NOW), ROLE_MIDFIELDER);
  EXPECT_EQ(assignRole(3, 800, ROLE_DEFENDER, {msg(2, 1200), msg(4, 1500)}, NOW), ROLE_STRIKER);
  EXPECT_EQ(assignRole(2, 500, ROLE_DEFENDER, messages, NOW), ROLE_STRIKER);
}

TEST(TeamRoles, GoalieIsFixedAndNeverStriker) {
  EXPECT_EQ(assignRole(1, 0, ROLE_GOALIE, {msg(2, 3000)}, NOW), ROLE_GOALIE);
  EXPECT_EQ(assignRole(2, 3000, ROLE_DEFENDER, {msg(1, 0, ROLE_GOALIE)}, NOW), ROLE_STRIKER);
}

TEST(TeamRoles, PenalisedAndStaleMessagesAreIgnored) {
  EXPECT_EQ(assignRole(2, 1200, ROLE_DEFENDER, {msg(3, 800, ROLE_DEFENDER, true), msg(4, 1500)}, NOW), ROLE_STRIKER);
  EXPECT_EQ(assignRole(2, 1200, ROLE_DEFENDER, {msg(3, 800, ROLE_DEFENDER, false, MESSAGE_STALE_US + 1)}, NOW),
            ROLE_STRIKER);
  EXPECT_EQ(assignRole(2, 1200, ROLE_DEFENDER, {msg(3, 800, ROLE_DEFENDER, false, MESSAGE_STALE_US)}, NOW),
            ROLE_DEFENDER);
  const TeamMessage truncated{3, NOW, std::vector<uint8_t>(VECTOR_1.begin(), VECTOR_1.end() - 1)};
  EXPECT_EQ(assignRole(2, 1200, ROLE_DEFENDER, {truncated}, NOW), ROLE_STRIKER);
}

TEST(TeamRoles, TiesGoToTheLowerNumberAndStrikersKeepAMargin) {
  EXPECT_EQ(assignRole(2, 1000, ROLE_DEFENDER, {msg(3, 1000)}, NOW), ROLE_STRIKER);
  EXPECT_EQ(assignRole(3, 1000, ROLE_DEFENDER, {msg(2, 1000)}, NOW), ROLE_DEFENDER);
  EXPECT_EQ(assignRole(2, 1000, ROLE_DEFENDER, {msg(3, 1200, ROLE_STRIKER)}, NOW), ROLE_DEFENDER);
  EXPECT_EQ(assignRole(2, 1000, ROLE_DEFENDER, {msg(3, 1400, ROLE_STRIKER)}, NOW), ROLE_STRIKER);
  EXPECT_EQ(assignRole(3, NO_BALL_DISTANCE, ROLE_DEFENDER, {msg(2, NO_BALL_DISTANCE)}, NOW), ROLE_DEFENDER);
}

// The Team: game states, messages, roles
TEST(TeamBehaviour, ReadyWalksToTheFormation) {
  expectPoint(readyPosition(1), -2700.f, 0.f);
  expectPoint(readyPosition(2), -700.f, 0.f);
  expectPoint(readyPosition(2, true), -150.f, -50.f); // inside the circle at the ball
  expectPoint(readyPosition(3, true), -1800.f, -600.f);
  expectPoint(readyPosition(3), -1800.f, -600.f);
  expectPoint(readyPosition(4), -1200.f, 900.f);
  expectPoint(readyPosition(5), -1800.f, 600.f);
  Blackboard ready = teamBoard({-2000.f, 0.f, 0.f}, 1000.f, 0.f, true, 0, GameState::READY, 2);
  ready.gameController.kickOffTeam = 1; // the other team kicks off: the formation's spot, straight ahead
  const auto command = Team().tick(ready);
  EXPECT_EQ(command.body.actionType, AT::WALK);
  EXPECT_NEAR(command.body.forward, 300.f, 1e-3f);
  EXPECT_EQ(command.body.turn, 0.f);
}

TEST(TeamBehaviour, TheKickerOfAKickOffPlaysTheBallAsPlayBegins) {
  // At its kick-off spot, the ball on the centre mark: it walks the ball on at once (the
  // opponents are outside the circle), where the striker of the other team walks to the ball.
  const AbsCoord spot{-150.f, -50.f, 0.f};
  const auto kicker = Team().tick(teamBoard(spot, 0.f, 0.f)).body;
  EXPECT_EQ(kicker.actionType, AT::WALK);
  EXPECT_NEAR(kicker.forward, carrySpeed(150.f), 1e-3f); // the ball 150 mm ahead
  Blackboard ready = teamBoard(spot, 1000.f, 0.f, true, 0, GameState::READY, 2);
  EXPECT_EQ(Team().tick(ready).body.actionType, AT::STAND); // arrived: it stays there
  ready.gameController.kickOffTeam = 1;                     // the other team kicks off: out of the circle
  EXPECT_EQ(Team().tick(ready).body.actionType, AT::WALK);
}

TEST(TeamBehaviour, InitialSetFinishedStandWithTheHeadOnTheBall) {
  for (const GameState state : {GameState::INITIAL, GameState::SET, GameState::FINISHED}) {
    const auto command = Team().tick(teamBoard({0.f, 0.f, 0.f}, 1000.f, 500.f, true, 0, state));
    EXPECT_EQ(command.body.actionType, AT::STAND);
    EXPECT_NEAR(command.head.yaw, 0.463648f, 1e-5f);
  }
}

TEST(TeamBehaviour, PenalisedAndFallenStand) {
  auto command = Team().tick(teamBoard({0.f, 0.f, 0.f}, 130.f, 50.f, true, 0, GameState::PLAYING, 2, true));
  EXPECT_EQ(command.body.actionType, AT::STAND);
  ASSERT_TRUE(decodeMessage(command.teamMessage));
  EXPECT_TRUE(decodeMessage(command.teamMessage)->penalised);
  command = Team().tick(teamBoard({0.f, 0.f, 0.f}, 130.f, 50.f, true, 0, GameState::PLAYING, 2, false, true));
  EXPECT_EQ(command.body.actionType, AT::STAND);
}

TEST(TeamBehaviour, SendsAMessageEverySixthFrame) {
  Team team;
  std::vector<size_t> sent;
  for (int i = 0; i < 13; ++i)
    sent.push_back(team.tick(teamBoard({0.f, 0.f, 0.f}, 1000.f, 0.f, true, 0, GameState::PLAYING, 3)).teamMessage.size());
  EXPECT_EQ(sent, (std::vector<size_t>{14, 0, 0, 0, 0, 0, 14, 0, 0, 0, 0, 0, 14}));
}

TEST(TeamBehaviour, PlayingTakesTheAssignedRole) {
  Team striker;
  const auto command = striker.tick(teamBoard({100.f, -200.f, 0.f}, 230.f, -150.f, true, 0, GameState::PLAYING, 3));
  EXPECT_EQ(striker.role(), ROLE_STRIKER); // alone: striker, carries
  EXPECT_EQ(command.body.actionType, AT::WALK);
  EXPECT_EQ(command.body.forward, CARRY_SPEED);
  EXPECT_EQ(decodeMessage(command.teamMessage),
            (TeamInfo{3, ROLE_STRIKER, true, false, false, 139, 230, -150, 100, -200}));
  Team defender;
  defender.tick(teamBoard({0.f, 0.f, 0.f}, 1000.f, 0.f, true, 0, GameState::PLAYING, 3, false, false, {msg(2, 300)}));
  EXPECT_EQ(defender.role(), ROLE_DEFENDER);
  Team goalie;
  goalie.tick(teamBoard({-2600.f, 0.f, 0.f}, 1000.f, 0.f, true, 0, GameState::PLAYING, 1));
  EXPECT_EQ(goalie.role(), ROLE_GOALIE);
}

TEST(TeamBehaviour, ALostBallMakesTheStrikerTurnToSearch) {
  Team team(ROLE_STRIKER);
  auto command = team.tick(teamBoard({0.f, 0.f, 0.f}, 0.f, -1000.f, false, SEARCH_TURN_FRAMES + 1));
  EXPECT_EQ(command.body.actionType, AT::WALK);
  EXPECT_NEAR(command.body.turn, -SEARCH_TURN_SPEED, 1e-6f);
  command = team.tick(teamBoard({0.f, 0.f, 0.f}, 0.f, -1000.f, false, SEARCH_TURN_FRAMES));
  EXPECT_EQ(command.body.actionType, AT::STAND); // not yet: LineUpAndKick stands while the ball is lost
  command = team.tick(teamBoard({0.f, 0.f, 0.f}, 0.f, -1000.f, false, SEARCH_TURN_FRAMES + SEARCH_TURN_LIMIT_FRAMES + 1));
  EXPECT_GT(command.body.forward, 0.f); // under a full turn, then off to a search spot
  EXPECT_EQ(command.body.turn, 0.f);
  command = team.tick(teamBoard({0.f, 0.f, 0.f}, 0.f, -1000.f, false, SEARCH_TURN_FRAMES + SEARCH_CYCLE_FRAMES + 1));
  EXPECT_NEAR(command.body.turn, -SEARCH_TURN_SPEED, 1e-6f); // the next search turn
}

TEST(TeamBehaviour, ASupporterTurnsToSearchOnlyAtHome) {
  Team team(ROLE_DEFENDER);
  auto command = team.tick(teamBoard({0.f, 0.f, 0.f}, 0.f, 1000.f, false, SEARCH_TURN_FRAMES + 1));
  EXPECT_NEAR(command.body.forward, -200.f, 1e-3f); // home (-1800, 0): backwards
  EXPECT_NEAR(command.body.turn, 0.f, 1e-5f);
  command = team.tick(teamBoard({-1800.f, 100.f, 0.f}, 0.f, 1000.f, false, SEARCH_TURN_FRAMES + 1));
  EXPECT_NEAR(command.body.turn, SEARCH_TURN_SPEED, 1e-6f);
}
