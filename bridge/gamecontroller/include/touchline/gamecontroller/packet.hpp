#pragma once
// Decoding the official SPL GameController's data packet (RoboCupGameControlData, sent
// over UDP to port 3838) into the world's GameInfo. Pure: bytes in, values out; no
// sockets (the receiver is touchline/gamecontroller/receiver.hpp).
//
// Supported: GAMECONTROLLER_STRUCT_VERSION 15 and 18, the versions of
// game_controller_msgs/headers/RoboCupGameControlData.h in RoboCup-SPL/GameController3
// (the Rust GameController in use since RoboCup 2023). Both lay the packet out the same
// way: 118 bytes, little-endian, no padding:
//
//   offset size
//        0    4  header "RGme"
//        4    1  version
//        5    1  packetNumber        (wraps around)
//        6    1  playersPerTeam
//        7    1  competitionPhase
//        8    1  competitionType
//        9    1  gamePhase
//       10    1  state               0 INITIAL 1 READY 2 SET 3 PLAYING 4 FINISHED, 5 STANDBY (18 only)
//       11    1  setPlay
//       12    1  firstHalf           1 first half, 0 otherwise
//       13    1  kickingTeam         a team NUMBER; 255 KICKING_TEAM_NONE (18 only)
//       14    2  secsRemaining       int16
//       16    2  secondaryTime       int16
//       18   50  teams[0], then 68 50 teams[1]; each:
//                  +0 teamNumber, +1 fieldPlayerColour, +2 goalkeeperColour, +3 goalkeeper,
//                  +4 score, +5 penaltyShot, +6 singleShots (uint16), +8 messageBudget (uint16),
//                  +10 players[20], each 2 bytes: penalty, secsTillUnpenalised
//
// Other versions (the Java GameController's 12 and older, 16 and 17) are rejected: their
// layouts could not be confirmed. GameController3 sends the monitor copy with the header
// "RGTD"; that is rejected too (wrong header).
//
// Which packet team is which of ours: GameController3 orders teams[] by the side each
// defends, so the order can change at half time. Give the decoder both team numbers
// (GameControllerConfig::team_numbers) to map by number; without them teams[0] is our
// team 0.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "touchline/frame.hpp"

namespace touchline::sim {

namespace gamecontroller {
constexpr char kHeader[4] = {'R', 'G', 'm', 'e'};
constexpr std::array<int, 2> kSupportedVersions{{15, 18}};
constexpr std::size_t kPacketSize = 118;  ///< both supported versions
constexpr int kMaxNumPlayers = 20;        ///< MAX_NUM_PLAYERS: player slots per team in the packet
constexpr int kStateStandby = 5;          ///< STATE_STANDBY (version 18)
constexpr int kKickingTeamNone = 255;     ///< KICKING_TEAM_NONE (version 18)
constexpr int kPenaltySubstitute = 14;    ///< PENALTY_SUBSTITUTE
constexpr uint16_t kDataPort = 3838;      ///< GAMECONTROLLER_DATA_PORT
} // namespace gamecontroller

/// A packet that is not a supported GameController data packet (or is inconsistent with
/// the configured team numbers). what() says why in one line.
class GameControllerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct GameControllerConfig {
  /// Team numbers of our team 0 and team 1 (0..255, distinct). Packets are mapped by
  /// number, and a packet carrying other teams is an error. Unset: teams[0] is our team 0.
  std::optional<std::array<int, 2>> team_numbers;
};

/// Throws std::invalid_argument if the configured team numbers are out of 0..255 or equal.
void validate(const GameControllerConfig& config);

/// One player's penalty as the GameController sends it.
struct PlayerPenalty {
  bool penalised = false;        ///< penalty != PENALTY_NONE (a substitute counts as penalised)
  int penalty = 0;               ///< the GameController's PENALTY_* code
  int secs_till_unpenalised = 0; ///< the GameController's estimate, seconds
};

/// A decoded packet. Everything indexed by team is in OUR team order (0, 1), whatever
/// the order in the packet.
struct GameControllerPacket {
  int version = 0;
  int packet_number = 0; ///< 0..255, wraps around
  int players_per_team = 0;
  int competition_phase = 0;
  int competition_type = 0;
  int game_phase = 0; ///< GAME_PHASE_*: 0 normal, 1 penalty shoot-out, 2 overtime, 3 timeout
  int set_play = 0;   ///< SET_PLAY_*, 0..5 (game.set_play says the same)
  int raw_state = 0;  ///< the packet's state number
  /// game.state (STATE_STANDBY of version 18 as kStandby), secs_remaining (the packet's, may
  /// be negative), first_half, score, kickoff_team = *kicking_team (0 when there is none:
  /// see kicking_team), and set_play with set_play_team = *kicking_team while one is on.
  GameInfo game;
  /// Our index of the team to kick off / take the set play; nullopt for KICKING_TEAM_NONE
  /// (version 18), where game.kickoff_team is 0 and callers should keep what they had.
  std::optional<int> kicking_team;
  int secondary_time = 0;             ///< seconds, may be negative
  std::array<int, 2> team_numbers{};  ///< our team i's number
  std::array<int, 2> packet_slot{};   ///< our team i is teams[packet_slot[i]] in the packet
  std::array<int, 2> message_budget{};
  /// [our team][player number - 1], players 1..kMaxTeamSize (the packet carries 20 slots;
  /// the rest are not kept).
  std::array<std::array<PlayerPenalty, kMaxTeamSize>, 2> penalties{};
};

/// Decodes `size` bytes at `data`. Throws GameControllerError (wrong header, unsupported
/// version, wrong size, an unknown state, firstHalf not 0 or 1, team numbers or kicking
/// team inconsistent with each other or the config), std::invalid_argument for an invalid
/// config. Checks in this order: at least 5 bytes, header, version, exact size, fields.
GameControllerPacket decode_gamecontroller_packet(const void* data, std::size_t size,
                                                  const GameControllerConfig& config = {});

} // namespace touchline::sim
