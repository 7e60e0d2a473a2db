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

/// A message that decoded but makes no sense (out-of-range ids, tick counts, NaNs).
struct MalformedMessage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Decodes raw bytes into `msg`; throws MalformedMessage naming the channel on failure
/// (wrong type fingerprint, truncated data).
template <typename Msg>
void decode(const void* data, int size, const std::string& channel, Msg& msg) {
  if (msg.decode(data, 0, size) < 0)
    throw MalformedMessage(channel + ": cannot decode as " + Msg::getTypeName() +
                           " (wrong type or corrupt, " + std::to_string(size) + " bytes)");
}

pose2d_t to_lcm(const Pose2D& pose);
sense_t to_lcm(const SenseFrame& frame);
SenseFrame from_lcm(const sense_t& msg); ///< throws MalformedMessage

act_t to_lcm(const RobotAct& act, int64_t utime, int64_t instance);
RobotAct from_lcm(const act_t& msg); ///< throws MalformedMessage

/// Wall-clock microseconds (steady), for the adapters' timeouts; robot code never sees it.
int64_t wall_us();

/// Checks team 0..1 and player 1..kMaxTeamSize. Throws MalformedMessage.
void check_id(int team, int player, const std::string& what);

} // namespace touchline::transport
