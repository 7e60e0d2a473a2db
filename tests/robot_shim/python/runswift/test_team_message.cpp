// BroadcastData as the bytes of a team message and back: what teammates read is what was
// sent, within the league's size bound; anything else is not taken for a broadcast.
#include "touchline/python/runswift/team_message.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace touchline::python::runswift;

namespace {

Broadcast sample() {
  Broadcast b;
  b.data.playerNum = 4;
  b.data.robotPos = {-1234.5f, 987.25f, -2.5f};
  b.data.ballPosAbs = {3000, -1500, 0};
  b.data.ballPosRR = {800, 0.75f};
  b.data.sharedStateEstimationBundle.haveBallUpdate = true;
  b.data.sharedStateEstimationBundle.ballVelRRC = {-120, 40, 0};
  b.data.behaviourSharedData.secondsSinceLastKick = 17;
  b.data.behaviourSharedData.role = 31;
  b.data.behaviourSharedData.playingBall = true;
  b.data.behaviourSharedData.isKickedOff = true;
  b.data.behaviourSharedData.walkingToX = 100;
  b.data.behaviourSharedData.walkingToY = -200;
  b.data.behaviourSharedData.walkingToH = 1.5f;
  b.data.acB = KICK;
  b.data.uptime = 42.5f;
  b.data.gameState = 3;
  b.fallen = true;
  b.ball_age_s = 0.5f;
  return b;
}

} // namespace

TEST(TeamMessage, ABroadcastComesBackAsSentWithinTheLeaguesSizeBound) {
  const auto bytes = encode_broadcast(sample());
  EXPECT_EQ(bytes.size(), kBroadcastBytes);
  EXPECT_LE(bytes.size(), 128u); // config [comm] max_bytes
  const auto back = decode_broadcast(bytes);
  ASSERT_TRUE(back);
  const BroadcastData& d = back->data;
  EXPECT_EQ(d.playerNum, 4);
  EXPECT_FLOAT_EQ(d.robotPos[0], -1234.5f);
  EXPECT_FLOAT_EQ(d.robotPos[1], 987.25f);
  EXPECT_FLOAT_EQ(d.robotPos[2], -2.5f);
  EXPECT_FLOAT_EQ(d.ballPosAbs.x, 3000);
  EXPECT_FLOAT_EQ(d.ballPosAbs.y, -1500);
  EXPECT_FLOAT_EQ(d.ballPosRR.distance, 800);
  EXPECT_FLOAT_EQ(d.ballPosRR.heading, 0.75f);
  EXPECT_TRUE(d.sharedStateEstimationBundle.haveBallUpdate);
  EXPECT_FLOAT_EQ(d.sharedStateEstimationBundle.ballVelRRC.x, -120);
  // the bundle's robot pose and robot-relative ball follow from what was sent
  EXPECT_FLOAT_EQ(d.sharedStateEstimationBundle.robotPos.x, -1234.5f);
  EXPECT_NEAR(d.sharedStateEstimationBundle.ballPosRRC.x, 800 * std::cos(0.75f), 1e-3);
  EXPECT_NEAR(d.sharedStateEstimationBundle.ballPosRRC.y, 800 * std::sin(0.75f), 1e-3);
  const BehaviourSharedData& s = d.behaviourSharedData;
  EXPECT_EQ(s.secondsSinceLastKick, 17);
  EXPECT_EQ(s.role, 31);
  EXPECT_TRUE(s.playingBall);
  EXPECT_FALSE(s.needAssistance);
  EXPECT_FALSE(s.isAssisting);
  EXPECT_TRUE(s.isKickedOff);
  EXPECT_FALSE(s.kickNotification);
  EXPECT_FLOAT_EQ(s.walkingToH, 1.5f);
  EXPECT_EQ(d.acB, KICK);
  EXPECT_FLOAT_EQ(d.uptime, 42.5f);
  EXPECT_EQ(d.gameState, 3);
  EXPECT_TRUE(back->fallen);
  EXPECT_FALSE(back->penalised);
  EXPECT_FLOAT_EQ(back->ball_age_s, 0.5f);
}

TEST(TeamMessage, NeverKickedIsMinusOneOnBothSides) {
  Broadcast b;
  const auto back = decode_broadcast(encode_broadcast(b));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->data.behaviourSharedData.secondsSinceLastKick, -1);
  EXPECT_EQ(back->data.acB, LIMP);
}

TEST(TeamMessage, OtherBytesAreNotABroadcast) {
  auto bytes = encode_broadcast(sample());
  EXPECT_FALSE(decode_broadcast({}));
  EXPECT_FALSE(decode_broadcast(std::vector<uint8_t>(bytes.begin(), bytes.end() - 1)));      // short
  auto longer = bytes;
  longer.push_back(0);
  EXPECT_FALSE(decode_broadcast(longer));
  auto other = bytes;
  other[0] = 'X'; // another team's format
  EXPECT_FALSE(decode_broadcast(other));
  auto version = bytes;
  version[2] = 2;
  EXPECT_FALSE(decode_broadcast(version));
  auto nan = bytes;
  const float q = std::nanf("");
  std::memcpy(&nan[10], &q, 4); // robot x
  EXPECT_FALSE(decode_broadcast(nan));
}
