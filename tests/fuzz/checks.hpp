#pragma once
// What every fuzz input must satisfy, shared by the bounded CTest harness and the libFuzzer
// target. For an LCM type: the generated decoder (hardened by
// lcm_types/harden_decoders.cmake) returns without throwing and allocates no more at once
// than the input's size justifies; transport::decode() and the validators the programs
// apply (from_lcm, from_snapshot) decode it or throw MalformedMessage, nothing else. For a
// GameController packet: a consistent packet or GameControllerError, nothing else.
#include <algorithm>
#include <string>

#include "all_lcm_types.hpp"
#include "allocation_meter.hpp"
#include "mutator.hpp"
#include "touchline/lcm/codec.hpp"
#include "touchline/lcm/snapshot.hpp"
#include "touchline/gamecontroller/packet.hpp"

namespace touchline::fuzz {

/// What an input did: decoded, or rejected as it should be; `failure` says what went wrong
/// otherwise (a bug).
struct Verdict {
  bool decoded = false;
  std::string failure;
};

template <typename... T>
constexpr size_t largest_sizeof() {
  return std::max({sizeof(T)...});
}
/// No element of a decoded array is larger than this, so a decoder that checks its counts
/// against the bytes left never allocates more than this per input byte.
constexpr size_t kLargestElementBytes = largest_sizeof<TOUCHLINE_ALL_LCM_TYPES>();

// What the receiving programs do with a decoded message: convert and validate it, or use
// it as it is.
inline void validate(const act_t& m) { transport::from_lcm(m); }
inline void validate(const sense_t& m) { transport::from_lcm(m); }
inline void validate(const blackboard_snapshot_t& m) { transport::from_snapshot(m); }
template <typename Msg>
void validate(const Msg&) {}

template <typename Msg>
Verdict check_lcm(const Bytes& bytes) {
  const int size = static_cast<int>(bytes.size());
  const std::string type = Msg::getTypeName();
  {
    Msg raw{};
    AllocationMeter meter;
    try {
      raw.decode(bytes.data(), 0, size);
    } catch (const std::exception& e) {
      return {false, "the generated " + type + " decoder threw \"" + e.what() + "\" on " + hex(bytes)};
    }
    const size_t limit = (bytes.size() + 1) * kLargestElementBytes;
    if (meter.largest() > limit)
      return {false, "the generated " + type + " decoder allocated " + std::to_string(meter.largest()) +
                         " bytes at once for a " + std::to_string(bytes.size()) + "-byte input (limit " +
                         std::to_string(limit) + "): " + hex(bytes)};
  }
  try {
    Msg msg;
    transport::decode(bytes.data(), size, "FUZZ", msg);
    validate(msg);
    return {true, ""};
  } catch (const transport::MalformedMessage&) {
    return {false, ""};
  } catch (const std::exception& e) {
    return {false, type + ": \"" + e.what() + "\" is not a MalformedMessage, on " + hex(bytes)};
  }
}

inline Verdict check_gamecontroller(const Bytes& bytes, const sim::GameControllerConfig& config) {
  sim::GameControllerPacket p;
  try {
    p = sim::decode_gamecontroller_packet(bytes.data(), bytes.size(), config);
  } catch (const sim::GameControllerError&) {
    return {false, ""};
  } catch (const std::exception& e) {
    return {false, std::string("\"") + e.what() + "\" is not a GameControllerError, on " + hex(bytes)};
  }
  const auto state = static_cast<int>(p.game.state);
  const bool standby = p.game.state == GameState::kStandby;
  const bool set_play = p.game.set_play != SetPlay::kNone;
  const bool consistent = state >= 0 && state <= static_cast<int>(GameState::kStandby) &&
                          (!standby || p.version == 18) &&
                          (set_play ? p.kicking_team && p.game.set_play_team == *p.kicking_team
                                    : p.game.set_play_team == -1) &&
                          (p.game.kickoff_team == 0 || p.game.kickoff_team == 1) &&
                          (!p.kicking_team || *p.kicking_team == p.game.kickoff_team) &&
                          p.team_numbers[0] != p.team_numbers[1] &&
                          ((p.packet_slot[0] == 0 && p.packet_slot[1] == 1) ||
                           (p.packet_slot[0] == 1 && p.packet_slot[1] == 0));
  if (!consistent) return {false, "decoded into an inconsistent packet: " + hex(bytes)};
  return {true, ""};
}

} // namespace touchline::fuzz
