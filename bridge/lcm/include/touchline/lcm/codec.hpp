#pragma once
// The LCM adapters' shared half: channel names, and conversion between the core frame
// types (touchline/frame.hpp) and their lcm_types messages, with validation, so a
// malformed message becomes one clear error instead of a crash.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "touchline/act_t.hpp"
#include "touchline/frame.hpp"
#include "touchline/sense_t.hpp"

namespace touchline::transport {

/// Default LCM URL: loopback-scoped multicast (ttl=0 never leaves the machine).
constexpr const char* kDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";

constexpr const char* kSenseChannel = "TL_SENSE";
constexpr const char* kTruthChannel = "TL_TRUTH";
constexpr const char* kGameChannel = "TL_GAME";
constexpr const char* kStatusChannel = "TL_STATUS";
constexpr const char* kEventChannel = "TL_EVENT";
constexpr const char* kJoinChannel = "TL_JOIN";
constexpr const char* kJoinReplyChannel = "TL_JOIN_REPLY";
constexpr const char* kActChannelPattern = "TL_ACT_.*";
constexpr const char* kSnapshotChannelPattern = "TL_BLACKBOARD_.*";
/// "TL_ACT_<team>_<player>"
std::string act_channel(RobotId id);

/// A message that cannot be decoded or makes no sense (wrong type, truncated, forged array
/// counts, out-of-range ids, tick counts, NaNs). The only exception decode() and from_lcm()
/// throw: a caller counts it and drops the message.
struct MalformedMessage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Highest frame index accepted from the bus. A day of play at 30 Hz is far beyond any
/// match; a frame number past it is forged or corrupt (and frame_start_utime() of a forged
/// 2^62 would overflow).
constexpr int64_t kMaxFrame = int64_t{30} * 3600 * 24;

/// Decodes the LCM encoding `data` (exactly `size` bytes: the Bus hands handlers the payload
/// without its tag) into `msg`, reset first so nothing of an earlier message survives.
/// Throws MalformedMessage naming the channel for a wrong type fingerprint, truncated data,
/// bytes left over, or an array count or string length that the bytes cannot hold; the
/// generated decoders reject those before allocating (lcm_types/harden_decoders.cmake).
/// Throws nothing else, whatever the bytes.
template <typename Msg>
void decode(const void* data, int size, const std::string& channel, Msg& msg) {
  msg = Msg{};
  int used = -1;
  try {
    used = msg.decode(data, 0, size);
  } catch (const std::exception&) {
    // Only if a future lcm-gen slips past harden_decoders.cmake (std::length_error,
    // std::bad_alloc): still a malformed message, never an exception through LCM.
  }
  if (used < 0)
    throw MalformedMessage(channel + ": cannot decode as " + Msg::getTypeName() +
                           " (wrong type or corrupt, " + std::to_string(size) + " bytes)");
  if (used != size)
    throw MalformedMessage(channel + ": " + std::to_string(size - used) + " bytes after the " +
                           Msg::getTypeName() + " (corrupt)");
}

/// Writes the GameController fields that sense_t and game_state_t both carry, under the same
/// names: the clock, kick-off team, score, set play and drop-in (drop_in_s saturates at the
/// wire's int16 after 9 hours).
template <class Msg>
void write_game_fields(const GameInfo& game, Msg& m) {
  m.secs_remaining = game.secs_remaining;
  m.kickoff_team = static_cast<int8_t>(game.kickoff_team);
  m.score[0] = static_cast<int8_t>(game.score[0]);
  m.score[1] = static_cast<int8_t>(game.score[1]);
  m.set_play = static_cast<int8_t>(game.set_play);
  m.set_play_team = static_cast<int8_t>(game.set_play_team);
  m.drop_in_team = static_cast<int8_t>(game.drop_in_team);
  m.drop_in_s = static_cast<int16_t>(game.drop_in_s < INT16_MAX ? game.drop_in_s : INT16_MAX);
}

pose2d_t to_lcm(const Pose2D& pose);
sense_t to_lcm(const SenseFrame& frame);
/// Throws MalformedMessage unless every field is in range: ids, frame 0..kMaxFrame with its
/// own utime and motion_ticks (frame.hpp), finite numbers, sonar 0..1, landmark ids that
/// exist, robots listed once, team messages from players 1..kMaxTeamSize sent by now.
SenseFrame from_lcm(const sense_t& msg);

act_t to_lcm(const RobotAct& act, int64_t utime, int64_t instance);
/// Throws MalformedMessage unless the id, frame 0..kMaxFrame, motion_ticks
/// 0..kMaxTicksPerFrame, CPU time >= 0 and finite numbers are in range.
RobotAct from_lcm(const act_t& msg);

/// Wall-clock microseconds (steady), for the adapters' timeouts; robot code never sees it.
int64_t wall_us();

/// Checks team 0..1 and player 1..kMaxTeamSize. Throws MalformedMessage.
void check_id(int team, int player, const std::string& what);

} // namespace touchline::transport
