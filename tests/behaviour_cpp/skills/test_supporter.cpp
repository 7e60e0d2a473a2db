// The supporters' numbers (SupporterDef): the tuned defender against the thesis's Algorithm
// 4.2, and the skill parameter supporters=tuned|thesis that picks them; the same hand-worked
// cases as tests/behaviour_py/test_supporter.py. (Algorithms 4.1 and 4.2 with the thesis's
// numbers: test_team.cpp.)
#include "touchline/behaviour/skills/supporter.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "boards.hpp"
#include "rejection.hpp"
#include "touchline/behaviour/registry.hpp"
#include "touchline/behaviour/skills/search.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::make_behaviour;
using touchline::behaviour::test::board;
using touchline::behaviour::test::rejection;
using touchline::behaviour::test::teamBoard;
using AT = ActionCommand::ActionType;

namespace {

void expectPoint(const FieldPoint& p, float x, float y) {
  EXPECT_NEAR(p.x, x, 1e-3f);
  EXPECT_NEAR(p.y, y, 1e-3f);
}

const AbsCoord THESIS_SPOT{-1250.f, 350.f, std::atan2(250.f, 1250.f)}; ///< the thesis defender's, ball (0, 600)
const AbsCoord TUNED_SPOT{-900.f, 420.f, std::atan2(180.f, 900.f)};    ///< the tuned defender's, ball (0, 600)

} // namespace

TEST(Supporter, TheTunedDefenderStandsCloserBehindTheBall) {
  // Ball at 0: 900 behind it (the thesis: 1250), y on the ball-own-goal line.
  expectPoint(defenderTarget(0.f, 600.f, tunedSupporters()), -900.f, 420.f);
  expectPoint(defenderTarget(0.f, 600.f, thesisSupporters()), -1250.f, 350.f);
  // Ball beyond 900: it stops at the -500 line (the thesis: beyond 1250, at -1200).
  expectPoint(defenderTarget(1500.f, -900.f, tunedSupporters()), -500.f, -500.f);
  expectPoint(defenderTarget(1500.f, -900.f, thesisSupporters()), -1200.f, -360.f);
  // Ball deep in the own half: the same fixed spot as the thesis's.
  expectPoint(defenderTarget(-1000.f, 400.f, tunedSupporters()), -1800.f, 0.f);
}

TEST(Supporter, TheTunedMidfielderIsTheThesisMidfielder) {
  for (const auto& [x, y] : {std::pair{2500.f, 300.f}, {1500.f, 200.f}, {-3000.f, 0.f}, {0.f, -700.f}}) {
    const FieldPoint tuned = midfielderTarget(x, y, 500.f, tunedSupporters());
    const FieldPoint thesis = midfielderTarget(x, y, 500.f, thesisSupporters());
    EXPECT_EQ(tuned.x, thesis.x);
    EXPECT_EQ(tuned.y, thesis.y);
  }
}

TEST(Supporter, ALostDefenderWalksToItsPresetsTargetForTheTeamBall) {
  const AbsCoord target = teamBallTarget(ROLE_DEFENDER, 0.f, 600.f, 0.f, tunedSupporters());
  EXPECT_NEAR(target.x, -900.f, 1e-3f);
  EXPECT_NEAR(target.y, 420.f, 1e-3f);
  EXPECT_NEAR(target.theta, std::atan2(180.f, 900.f), 1e-5f);
}

TEST(Supporter, ADefenderStandsOnlyAtItsOwnPresetsTarget) {
  const Blackboard thesisSpot = board(THESIS_SPOT, 0.f, 600.f);
  const Blackboard tunedSpot = board(TUNED_SPOT, 0.f, 600.f);
  EXPECT_EQ(Defender(thesisSupporters()).tick(thesisSpot).body.actionType, AT::STAND);
  EXPECT_EQ(Defender(tunedSupporters()).tick(tunedSpot).body.actionType, AT::STAND);
  const ActionCommand::Body walk = Defender(tunedSupporters()).tick(thesisSpot).body;
  EXPECT_EQ(walk.actionType, AT::WALK);
  EXPECT_GT(walk.forward, 0.f); // 350 mm further up
  EXPECT_EQ(Defender(thesisSupporters()).tick(tunedSpot).body.actionType, AT::WALK);
}

TEST(Supporter, TheSupportersParameterPicksTheNumbers) {
  // Player 3, with player 2 nearer the ball: Team makes it the defender, as Defender is.
  TeamMessage nearer;
  nearer.playerNumber = 2;
  nearer.data = encodeMessage(makeTeamInfo(2, ROLE_STRIKER, true, false, false, 100.f, 0.f, 600.f, -100.f, 600.f));
  const Blackboard thesisSpot = teamBoard(THESIS_SPOT, 0.f, 600.f, true, 0, GameState::PLAYING, 3, false, false, {nearer});
  for (const std::string skill : {"Team", "Defender"}) {
    EXPECT_EQ(make_behaviour(skill, {{"supporters", "thesis"}})->tick(thesisSpot).body.actionType, AT::STAND) << skill;
    EXPECT_EQ(make_behaviour(skill, {})->tick(thesisSpot).body.actionType, AT::WALK) << skill; // tuned: the default
  }
}

TEST(Supporter, TheDefaultIsTunedAndBothAreNamed) {
  EXPECT_EQ(supporterDefNames(), (std::vector<std::string>{"tuned", "thesis"}));
  EXPECT_EQ(supporterDef("tuned"), &tunedSupporters());
  EXPECT_EQ(supporterDef("thesis"), &thesisSupporters());
  EXPECT_EQ(supporterDef("best"), nullptr);
}

TEST(Supporter, ABadSupportersParameterIsOneLine) {
  EXPECT_EQ(rejection("Team", {{"supporters", "best"}}), "Team: parameter supporters must be tuned or thesis (got 'best')");
  EXPECT_EQ(rejection("Midfielder", {{"supporters", ""}}),
            "Midfielder: parameter supporters must be tuned or thesis (got '')");
  EXPECT_EQ(rejection("GoToBall", {{"supporters", "thesis"}}), "GoToBall: unknown parameter 'supporters'");
}
