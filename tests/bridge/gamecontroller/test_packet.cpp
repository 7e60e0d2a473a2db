#include "touchline/gamecontroller/packet.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

using namespace touchline;
using sim::decode_gamecontroller_packet;
using sim::GameControllerConfig;
using sim::GameControllerError;
using sim::GameControllerPacket;

namespace {

// A RoboCupGameControlData as the fields of
// RoboCup-SPL/GameController3 game_controller_msgs/headers/RoboCupGameControlData.h
// (versions 15 and 18) name them, serialised field by field, little-endian, unpadded.
struct RawPlayer {
  uint8_t penalty = 0;
  uint8_t secsTillUnpenalised = 0;
};
struct RawTeam {
  uint8_t teamNumber = 0;
  uint8_t fieldPlayerColour = 0;
  uint8_t goalkeeperColour = 0;
  uint8_t goalkeeper = 1;
  uint8_t score = 0;
  uint8_t penaltyShot = 0;
  uint16_t singleShots = 0;
  uint16_t messageBudget = 1200;
  RawPlayer players[20];
};
struct RawPacket {
  char header[4] = {'R', 'G', 'm', 'e'};
  uint8_t version = 15;
  uint8_t packetNumber = 0;
  uint8_t playersPerTeam = 5;
  uint8_t competitionPhase = 0;
  uint8_t competitionType = 0;
  uint8_t gamePhase = 0;
  uint8_t state = 0;
  uint8_t setPlay = 0;
  uint8_t firstHalf = 1;
  uint8_t kickingTeam = 0;
  int16_t secsRemaining = 600;
  int16_t secondaryTime = 0;
  RawTeam teams[2];

  RawPacket() {
    teams[0].teamNumber = 5;
    teams[1].teamNumber = 12;
    kickingTeam = 5;
  }
};

void put_u8(std::vector<uint8_t>& out, uint8_t v) { out.push_back(v); }
void put_u16(std::vector<uint8_t>& out, uint16_t v) {
  out.push_back(static_cast<uint8_t>(v & 0xff));
  out.push_back(static_cast<uint8_t>(v >> 8));
}
void put_i16(std::vector<uint8_t>& out, int16_t v) { put_u16(out, static_cast<uint16_t>(v)); }

std::vector<uint8_t> serialise(const RawPacket& p) {
  std::vector<uint8_t> out;
  for (char c : p.header) put_u8(out, static_cast<uint8_t>(c));
  put_u8(out, p.version);
  put_u8(out, p.packetNumber);
  put_u8(out, p.playersPerTeam);
  put_u8(out, p.competitionPhase);
  put_u8(out, p.competitionType);
  put_u8(out, p.gamePhase);
  put_u8(out, p.state);
  put_u8(out, p.setPlay);
  put_u8(out, p.firstHalf);
  put_u8(out, p.kickingTeam);
  put_i16(out, p.secsRemaining);
  put_i16(out, p.secondaryTime);
  for (const RawTeam& t : p.teams) {
    put_u8(out, t.teamNumber);
    put_u8(out, t.fieldPlayerColour);
    put_u8(out, t.goalkeeperColour);
    put_u8(out, t.goalkeeper);
    put_u8(out, t.score);
    put_u8(out, t.penaltyShot);
    put_u16(out, t.singleShots);
    put_u16(out, t.messageBudget);
    for (const RawPlayer& pl : t.players) {
      put_u8(out, pl.penalty);
      put_u8(out, pl.secsTillUnpenalised);
    }
  }
  return out;
}

GameControllerPacket decode(const std::vector<uint8_t>& bytes, const GameControllerConfig& config = {}) {
  return decode_gamecontroller_packet(bytes.data(), bytes.size(), config);
}
GameControllerPacket decode(const RawPacket& p, const GameControllerConfig& config = {}) {
  return decode(serialise(p), config);
}

std::string error_of(const std::vector<uint8_t>& bytes, const GameControllerConfig& config = {}) {
  try {
    decode(bytes, config);
  } catch (const GameControllerError& e) {
    return e.what();
  }
  return "(decoded)";
}
std::string error_of(const RawPacket& p, const GameControllerConfig& config = {}) {
  return error_of(serialise(p), config);
}

GameControllerConfig teams(int team0, int team1) {
  GameControllerConfig c;
  c.team_numbers = std::array<int, 2>{{team0, team1}};
  return c;
}

} // namespace

TEST(GameControllerPacket, SerialisedSizeIsTheDocumentedSize) {
  EXPECT_EQ(serialise(RawPacket{}).size(), 118u);
  EXPECT_EQ(sim::gamecontroller::kPacketSize, 118u);
}

TEST(GameControllerPacket, DecodesEveryField) {
  RawPacket raw;
  raw.packetNumber = 201;
  raw.playersPerTeam = 7;
  raw.competitionPhase = 1;
  raw.competitionType = 1;
  raw.gamePhase = 2;
  raw.state = 3; // PLAYING
  raw.setPlay = 4;
  raw.firstHalf = 0;
  raw.kickingTeam = 12;
  raw.secsRemaining = 437; // 0x01b5: both bytes matter
  raw.secondaryTime = -3;
  raw.teams[0].score = 2;
  raw.teams[0].messageBudget = 0x1234;
  raw.teams[1].score = 3;
  raw.teams[1].messageBudget = 777;
  raw.teams[0].players[2] = {2, 27};  // player 3: pushing, 27 s left
  raw.teams[1].players[0] = {4, 0};   // player 1: inactive, no estimate
  raw.teams[1].players[6] = {14, 0};  // player 7: substitute

  const GameControllerPacket p = decode(raw);
  EXPECT_EQ(p.version, 15);
  EXPECT_EQ(p.packet_number, 201);
  EXPECT_EQ(p.players_per_team, 7);
  EXPECT_EQ(p.competition_phase, 1);
  EXPECT_EQ(p.competition_type, 1);
  EXPECT_EQ(p.game_phase, 2);
  EXPECT_EQ(p.set_play, 4);
  EXPECT_EQ(p.game.set_play, SetPlay::kKickIn);
  EXPECT_EQ(p.game.set_play_team, 1); // the kicking team takes the set play
  EXPECT_EQ(p.raw_state, 3);
  EXPECT_EQ(p.game.state, GameState::kPlaying);
  EXPECT_FALSE(p.game.first_half);
  EXPECT_EQ(p.game.secs_remaining, 437);
  EXPECT_EQ(p.secondary_time, -3);
  ASSERT_TRUE(p.kicking_team.has_value());
  EXPECT_EQ(*p.kicking_team, 1);
  EXPECT_EQ(p.game.kickoff_team, 1);
  EXPECT_EQ(p.game.score, (std::array<int, 2>{{2, 3}}));
  EXPECT_EQ(p.team_numbers, (std::array<int, 2>{{5, 12}}));
  EXPECT_EQ(p.packet_slot, (std::array<int, 2>{{0, 1}}));
  EXPECT_EQ(p.message_budget, (std::array<int, 2>{{0x1234, 777}}));

  for (int team = 0; team < 2; ++team)
    for (int i = 0; i < kMaxTeamSize; ++i) {
      const sim::PlayerPenalty& pen = p.penalties[team][i];
      const bool expected = (team == 0 && i == 2) || (team == 1 && (i == 0 || i == 6));
      EXPECT_EQ(pen.penalised, expected) << "team " << team << " player " << i + 1;
    }
  EXPECT_EQ(p.penalties[0][2].penalty, 2);
  EXPECT_EQ(p.penalties[0][2].secs_till_unpenalised, 27);
  EXPECT_EQ(p.penalties[1][0].penalty, 4);
  EXPECT_EQ(p.penalties[1][0].secs_till_unpenalised, 0);
  EXPECT_EQ(p.penalties[1][6].penalty, sim::gamecontroller::kPenaltySubstitute);
  EXPECT_EQ(p.penalties[0][0].penalty, 0);
}

TEST(GameControllerPacket, SecsRemainingIsSignedLittleEndian) {
  RawPacket raw;
  raw.secsRemaining = -17;
  EXPECT_EQ(decode(raw).game.secs_remaining, -17);
  raw.secsRemaining = 0x7fff;
  EXPECT_EQ(decode(raw).game.secs_remaining, 32767);
  raw.secsRemaining = 0x0100;
  EXPECT_EQ(decode(raw).game.secs_remaining, 256);
  // The byte order on the wire, independent of the helper.
  std::vector<uint8_t> bytes = serialise(RawPacket{});
  bytes[14] = 0x58;
  bytes[15] = 0x02;
  EXPECT_EQ(decode(bytes).game.secs_remaining, 600);
}

TEST(GameControllerPacket, MapsEveryState) {
  const GameState expected[] = {GameState::kInitial, GameState::kReady, GameState::kSet, GameState::kPlaying,
                                GameState::kFinished};
  for (uint8_t version : {uint8_t{15}, uint8_t{18}})
    for (uint8_t s = 0; s < 5; ++s) {
      RawPacket raw;
      raw.version = version;
      raw.state = s;
      const GameControllerPacket p = decode(raw);
      EXPECT_EQ(p.game.state, expected[s]) << "version " << int{version} << " state " << int{s};
    }
}

TEST(GameControllerPacket, StandbyInVersion18IsStandby) {
  RawPacket raw;
  raw.version = 18;
  raw.state = 5;
  const GameControllerPacket p = decode(raw);
  EXPECT_EQ(p.version, 18);
  EXPECT_EQ(p.game.state, GameState::kStandby);
  EXPECT_EQ(p.raw_state, 5);
}

TEST(GameControllerPacket, EverySetPlayIsTakenByTheKickingTeam) {
  const SetPlay expected[] = {SetPlay::kNone, SetPlay::kGoalKick, SetPlay::kPushingFreeKick,
                              SetPlay::kCornerKick, SetPlay::kKickIn, SetPlay::kPenaltyKick};
  for (uint8_t set_play = 0; set_play < 6; ++set_play) {
    RawPacket raw;
    raw.setPlay = set_play;
    raw.kickingTeam = raw.teams[1].teamNumber;
    const GameControllerPacket p = decode(raw);
    EXPECT_EQ(p.game.set_play, expected[set_play]);
    EXPECT_EQ(p.game.set_play_team, set_play == 0 ? -1 : 1) << int{set_play};
  }
}

TEST(GameControllerPacket, AnUnknownSetPlayOrOneWithNoKickingTeamIsAnError) {
  RawPacket raw;
  raw.setPlay = 6;
  EXPECT_EQ(error_of(raw), "GameController packet: unknown setPlay 6");
  raw.version = 18;
  raw.setPlay = 2;
  raw.kickingTeam = 255; // KICKING_TEAM_NONE
  EXPECT_EQ(error_of(raw), "GameController packet: setPlay 2 with no kicking team");
}

TEST(GameControllerPacket, UnknownStatesAreErrors) {
  RawPacket raw;
  raw.state = 5; // no STANDBY in version 15
  EXPECT_EQ(error_of(raw), "GameController packet: unknown state 5 in version 15");
  raw.version = 18;
  raw.state = 6;
  EXPECT_EQ(error_of(raw), "GameController packet: unknown state 6 in version 18");
  raw.state = 255;
  EXPECT_EQ(error_of(raw), "GameController packet: unknown state 255 in version 18");
}

TEST(GameControllerPacket, FirstHalfMustBeZeroOrOne) {
  RawPacket raw;
  raw.firstHalf = 1;
  EXPECT_TRUE(decode(raw).game.first_half);
  raw.firstHalf = 0;
  EXPECT_FALSE(decode(raw).game.first_half);
  raw.firstHalf = 2;
  EXPECT_EQ(error_of(raw), "GameController packet: firstHalf 2 is not 0 or 1");
}

TEST(GameControllerPacket, KickingTeamNoneInVersion18) {
  RawPacket raw;
  raw.version = 18;
  raw.kickingTeam = 255;
  const GameControllerPacket p = decode(raw);
  EXPECT_FALSE(p.kicking_team.has_value());
  EXPECT_EQ(p.game.kickoff_team, 0);
  // Version 15 has no KICKING_TEAM_NONE: 255 is a team number, and neither team's.
  raw.version = 15;
  EXPECT_EQ(error_of(raw), "GameController packet: kickingTeam 255 is neither team (5, 12)");
}

TEST(GameControllerPacket, KickingTeamOfNeitherTeamIsAnError) {
  RawPacket raw;
  raw.kickingTeam = 7;
  EXPECT_EQ(error_of(raw), "GameController packet: kickingTeam 7 is neither team (5, 12)");
}

TEST(GameControllerPacket, DefaultMappingIsPacketOrder) {
  RawPacket raw;
  raw.teams[0].teamNumber = 40;
  raw.teams[1].teamNumber = 3;
  raw.kickingTeam = 40;
  raw.teams[0].score = 1;
  const GameControllerPacket p = decode(raw);
  EXPECT_EQ(p.team_numbers, (std::array<int, 2>{{40, 3}}));
  EXPECT_EQ(p.game.kickoff_team, 0);
  EXPECT_EQ(p.game.score, (std::array<int, 2>{{1, 0}}));
}

TEST(GameControllerPacket, ConfiguredTeamNumbersMapByNumber) {
  // The GameController lists team 12 first (say, after half time): our team 0 is 5.
  RawPacket raw;
  raw.teams[0].teamNumber = 12;
  raw.teams[1].teamNumber = 5;
  raw.teams[0].score = 4;
  raw.teams[1].score = 1;
  raw.teams[0].messageBudget = 100;
  raw.teams[1].messageBudget = 200;
  raw.teams[0].players[1] = {6, 30}; // team 12's player 2
  raw.teams[1].players[4] = {5, 45}; // team 5's player 5
  raw.kickingTeam = 5;

  const GameControllerPacket p = decode(raw, teams(5, 12));
  EXPECT_EQ(p.team_numbers, (std::array<int, 2>{{5, 12}}));
  EXPECT_EQ(p.packet_slot, (std::array<int, 2>{{1, 0}}));
  EXPECT_EQ(p.game.score, (std::array<int, 2>{{1, 4}}));
  EXPECT_EQ(p.message_budget, (std::array<int, 2>{{200, 100}}));
  EXPECT_EQ(p.game.kickoff_team, 0);
  EXPECT_TRUE(p.penalties[0][4].penalised);
  EXPECT_EQ(p.penalties[0][4].secs_till_unpenalised, 45);
  EXPECT_TRUE(p.penalties[1][1].penalised);
  EXPECT_EQ(p.penalties[1][1].penalty, 6);
  EXPECT_FALSE(p.penalties[0][1].penalised);
  EXPECT_FALSE(p.penalties[1][4].penalised);

  // The same packet with the pair the other way round.
  const GameControllerPacket q = decode(raw, teams(12, 5));
  EXPECT_EQ(q.game.score, (std::array<int, 2>{{4, 1}}));
  EXPECT_EQ(q.game.kickoff_team, 1);
  EXPECT_TRUE(q.penalties[1][4].penalised);
}

TEST(GameControllerPacket, TeamsOtherThanConfiguredAreAnError) {
  RawPacket raw; // teams 5 and 12
  EXPECT_EQ(error_of(raw, teams(5, 13)), "GameController packet: teams 5 and 12, expected 5 and 13");
  EXPECT_EQ(error_of(raw, teams(1, 2)), "GameController packet: teams 5 and 12, expected 1 and 2");
}

TEST(GameControllerPacket, BothTeamsWithOneNumberIsAnError) {
  RawPacket raw;
  raw.teams[1].teamNumber = 5;
  EXPECT_EQ(error_of(raw), "GameController packet: both teams have team number 5");
}

TEST(GameControllerPacket, InvalidConfigIsInvalidArgument) {
  const std::vector<uint8_t> bytes = serialise(RawPacket{});
  EXPECT_THROW(decode(bytes, teams(5, 5)), std::invalid_argument);
  EXPECT_THROW(decode(bytes, teams(-1, 5)), std::invalid_argument);
  EXPECT_THROW(decode(bytes, teams(5, 256)), std::invalid_argument);
  EXPECT_NO_THROW(sim::validate(teams(0, 255)));
  EXPECT_NO_THROW(sim::validate(GameControllerConfig{}));
}

TEST(GameControllerPacket, OnlyTheFirstSevenPlayersAreKept) {
  RawPacket raw;
  for (int i = kMaxTeamSize; i < 20; ++i) raw.teams[0].players[i] = {14, 0};
  const GameControllerPacket p = decode(raw);
  for (const auto& team : p.penalties)
    for (const sim::PlayerPenalty& pen : team) EXPECT_FALSE(pen.penalised);
}

TEST(GameControllerPacket, WrongHeader) {
  RawPacket raw;
  raw.header[3] = 'x';
  EXPECT_EQ(error_of(raw), "GameController packet: header \"RGmx\", expected \"RGme\"");
  // GameController3's copy for monitors.
  raw.header[2] = 'T';
  raw.header[3] = 'D';
  EXPECT_EQ(error_of(raw), "GameController packet: header \"RGTD\", expected \"RGme\"");
  // The return packet robots send.
  raw.header[2] = 'r';
  raw.header[3] = 't';
  EXPECT_EQ(error_of(raw), "GameController packet: header \"RGrt\", expected \"RGme\"");
  std::vector<uint8_t> bytes = serialise(RawPacket{});
  bytes[0] = 0;
  bytes[1] = 0xff;
  EXPECT_EQ(error_of(bytes), "GameController packet: header \"\\x00\\xffme\", expected \"RGme\"");
}

TEST(GameControllerPacket, WrongVersion) {
  for (uint8_t v : {uint8_t{0}, uint8_t{12}, uint8_t{14}, uint8_t{16}, uint8_t{17}, uint8_t{19}, uint8_t{255}}) {
    RawPacket raw;
    raw.version = v;
    EXPECT_EQ(error_of(raw), "GameController packet: version " + std::to_string(v) +
                                 " is not supported (supported: 15, 18)");
  }
}

TEST(GameControllerPacket, WrongSize) {
  std::vector<uint8_t> bytes = serialise(RawPacket{});
  bytes.push_back(0);
  EXPECT_EQ(error_of(bytes), "GameController packet: 119 bytes, expected 118 for version 15");
  bytes.resize(117);
  EXPECT_EQ(error_of(bytes), "GameController packet: 117 bytes, expected 118 for version 15");
  bytes.resize(5);
  EXPECT_EQ(error_of(bytes), "GameController packet: 5 bytes, expected 118 for version 15");
  bytes.resize(4);
  EXPECT_EQ(error_of(bytes), "GameController packet: 4 bytes, too short for a header and a version");
  bytes.clear();
  EXPECT_EQ(error_of(bytes), "GameController packet: 0 bytes, too short for a header and a version");
  EXPECT_THROW(decode_gamecontroller_packet(nullptr, 0), GameControllerError);
  EXPECT_THROW(decode_gamecontroller_packet(nullptr, 118), GameControllerError);
}

TEST(GameControllerPacket, EveryTruncationIsAnError) {
  const std::vector<uint8_t> bytes = serialise(RawPacket{});
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_THROW(decode_gamecontroller_packet(bytes.data(), n), GameControllerError) << n << " bytes";
}

TEST(GameControllerPacket, GarbageNeverCrashes) {
  // Random bytes, and valid packets with random bytes changed: each either decodes or
  // throws GameControllerError, nothing else.
  std::mt19937 rng(1234);
  std::uniform_int_distribution<int> byte(0, 255);
  const std::vector<uint8_t> valid = serialise(RawPacket{});
  int decoded = 0, rejected = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<uint8_t> bytes;
    if (trial % 2 == 0) {
      bytes.resize(static_cast<std::size_t>(std::uniform_int_distribution<int>(0, 300)(rng)));
      for (auto& b : bytes) b = static_cast<uint8_t>(byte(rng));
      if (trial % 4 == 0 && bytes.size() >= 5) {
        bytes[0] = 'R', bytes[1] = 'G', bytes[2] = 'm', bytes[3] = 'e', bytes[4] = 15;
      }
    } else {
      bytes = valid;
      const int changes = std::uniform_int_distribution<int>(1, 4)(rng);
      for (int c = 0; c < changes; ++c)
        bytes[static_cast<std::size_t>(std::uniform_int_distribution<int>(0, 117)(rng))] =
            static_cast<uint8_t>(byte(rng));
    }
    try {
      decode(bytes);
      ++decoded;
    } catch (const GameControllerError&) {
      ++rejected;
    }
  }
  EXPECT_GT(decoded, 0);
  EXPECT_GT(rejected, 0);
}
