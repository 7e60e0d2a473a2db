#include "touchline/gamecontroller/packet.hpp"

#include <cstdio>

namespace touchline::sim {

namespace gc = gamecontroller;

namespace {

// Field offsets (see the layout in the header).
constexpr std::size_t kVersionAt = 4;
constexpr std::size_t kPacketNumberAt = 5;
constexpr std::size_t kPlayersPerTeamAt = 6;
constexpr std::size_t kCompetitionPhaseAt = 7;
constexpr std::size_t kCompetitionTypeAt = 8;
constexpr std::size_t kGamePhaseAt = 9;
constexpr std::size_t kStateAt = 10;
constexpr std::size_t kSetPlayAt = 11;
constexpr std::size_t kFirstHalfAt = 12;
constexpr std::size_t kKickingTeamAt = 13;
constexpr std::size_t kSecsRemainingAt = 14;
constexpr std::size_t kSecondaryTimeAt = 16;
constexpr std::size_t kTeamsAt = 18;
constexpr std::size_t kTeamSize = 10 + 2 * gc::kMaxNumPlayers;
// Within a team.
constexpr std::size_t kTeamNumberAt = 0;
constexpr std::size_t kScoreAt = 4;
constexpr std::size_t kMessageBudgetAt = 8;
constexpr std::size_t kPlayersAt = 10;
static_assert(kTeamsAt + 2 * kTeamSize == gc::kPacketSize, "layout adds up to the packet size");

class Reader {
 public:
  explicit Reader(const uint8_t* bytes) : bytes_(bytes) {}
  int u8(std::size_t at) const { return bytes_[at]; }
  int u16(std::size_t at) const { return bytes_[at] | (bytes_[at + 1] << 8); }
  int i16(std::size_t at) const {
    const int u = u16(at);
    return u >= 0x8000 ? u - 0x10000 : u;
  }

 private:
  const uint8_t* bytes_;
};

std::string printable(const uint8_t* bytes, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    const int c = bytes[i];
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}

std::string supported_versions() {
  std::string out;
  for (int v : gc::kSupportedVersions) out += (out.empty() ? "" : ", ") + std::to_string(v);
  return out;
}

[[noreturn]] void fail(const std::string& why) {
  throw GameControllerError("GameController packet: " + why);
}

} // namespace

void validate(const GameControllerConfig& config) {
  if (!config.team_numbers) return;
  const auto& n = *config.team_numbers;
  for (int i = 0; i < 2; ++i)
    if (n[i] < 0 || n[i] > 255)
      throw std::invalid_argument("GameController team number " + std::to_string(n[i]) + " is not in 0..255");
  if (n[0] == n[1])
    throw std::invalid_argument("GameController team numbers must differ (both " + std::to_string(n[0]) + ")");
}

GameControllerPacket decode_gamecontroller_packet(const void* data, std::size_t size,
                                                  const GameControllerConfig& config) {
  validate(config);
  const auto* bytes = static_cast<const uint8_t*>(data);
  if (bytes == nullptr || size <= kVersionAt)
    fail(std::to_string(size) + " bytes, too short for a header and a version");
  for (std::size_t i = 0; i < 4; ++i)
    if (bytes[i] != static_cast<uint8_t>(gc::kHeader[i]))
      fail("header \"" + printable(bytes, 4) + "\", expected \"RGme\"");
  const Reader r(bytes);
  const int version = r.u8(kVersionAt);
  bool supported = false;
  for (int v : gc::kSupportedVersions) supported = supported || v == version;
  if (!supported)
    fail("version " + std::to_string(version) + " is not supported (supported: " + supported_versions() + ")");
  if (size != gc::kPacketSize)
    fail(std::to_string(size) + " bytes, expected " + std::to_string(gc::kPacketSize) + " for version " +
         std::to_string(version));

  GameControllerPacket p;
  p.version = version;
  p.packet_number = r.u8(kPacketNumberAt);
  p.players_per_team = r.u8(kPlayersPerTeamAt);
  p.competition_phase = r.u8(kCompetitionPhaseAt);
  p.competition_type = r.u8(kCompetitionTypeAt);
  p.game_phase = r.u8(kGamePhaseAt);
  p.set_play = r.u8(kSetPlayAt);

  p.raw_state = r.u8(kStateAt);
  if (p.raw_state <= static_cast<int>(GameState::kFinished)) {
    p.game.state = static_cast<GameState>(p.raw_state);
  } else if (p.raw_state == gc::kStateStandby && version >= 18) {
    p.game.state = GameState::kStandby;
  } else {
    fail("unknown state " + std::to_string(p.raw_state) + " in version " + std::to_string(version));
  }

  const int first_half = r.u8(kFirstHalfAt);
  if (first_half > 1) fail("firstHalf " + std::to_string(first_half) + " is not 0 or 1");
  p.game.first_half = first_half == 1;
  p.game.secs_remaining = r.i16(kSecsRemainingAt);
  p.secondary_time = r.i16(kSecondaryTimeAt);

  // Which packet slot holds which of our teams.
  const std::array<int, 2> slot_numbers{{r.u8(kTeamsAt + kTeamNumberAt), r.u8(kTeamsAt + kTeamSize + kTeamNumberAt)}};
  if (slot_numbers[0] == slot_numbers[1])
    fail("both teams have team number " + std::to_string(slot_numbers[0]));
  if (config.team_numbers) {
    for (int team = 0; team < 2; ++team) {
      const int number = (*config.team_numbers)[team];
      if (slot_numbers[0] == number) p.packet_slot[team] = 0;
      else if (slot_numbers[1] == number) p.packet_slot[team] = 1;
      else
        fail("teams " + std::to_string(slot_numbers[0]) + " and " + std::to_string(slot_numbers[1]) +
             ", expected " + std::to_string((*config.team_numbers)[0]) + " and " +
             std::to_string((*config.team_numbers)[1]));
    }
  } else {
    p.packet_slot = {{0, 1}};
  }

  for (int team = 0; team < 2; ++team) {
    const std::size_t at = kTeamsAt + kTeamSize * static_cast<std::size_t>(p.packet_slot[team]);
    p.team_numbers[team] = r.u8(at + kTeamNumberAt);
    p.game.score[team] = r.u8(at + kScoreAt);
    p.message_budget[team] = r.u16(at + kMessageBudgetAt);
    for (int i = 0; i < kMaxTeamSize; ++i) {
      const std::size_t player_at = at + kPlayersAt + 2 * static_cast<std::size_t>(i);
      PlayerPenalty& pen = p.penalties[team][i];
      pen.penalty = r.u8(player_at);
      pen.secs_till_unpenalised = r.u8(player_at + 1);
      pen.penalised = pen.penalty != 0;
    }
  }

  const int kicking = r.u8(kKickingTeamAt);
  if (kicking == gc::kKickingTeamNone && version >= 18) {
    p.kicking_team.reset();
    p.game.kickoff_team = 0;
  } else if (kicking == p.team_numbers[0] || kicking == p.team_numbers[1]) {
    p.kicking_team = kicking == p.team_numbers[0] ? 0 : 1;
    p.game.kickoff_team = *p.kicking_team;
  } else {
    fail("kickingTeam " + std::to_string(kicking) + " is neither team (" + std::to_string(p.team_numbers[0]) +
         ", " + std::to_string(p.team_numbers[1]) + ")");
  }

  if (p.set_play > static_cast<int>(SetPlay::kPenaltyKick)) fail("unknown setPlay " + std::to_string(p.set_play));
  p.game.set_play = static_cast<SetPlay>(p.set_play);
  if (p.game.set_play != SetPlay::kNone) {
    if (!p.kicking_team) fail("setPlay " + std::to_string(p.set_play) + " with no kicking team");
    p.game.set_play_team = *p.kicking_team;
  }
  return p;
}

} // namespace touchline::sim
