#pragma once
// What a rUNSWift robot broadcasts (BroadcastData) as the bytes of a Touchline team
// message, and back. On the robot their C++ packs BroadcastData behind the SPL standard
// message; here the profile packs it into the radio model's message (config [comm]:
// at most max_bytes, max_rate_hz), so teammates' blackboard.receiver.data fills as there.
// Layout (little-endian, kBroadcastBytes): "RS", version, player, flags, body action, game
// state, role, seconds since the last kick (int16), then float32s: robot x, y, theta;
// ball x, y; ball distance, heading; ball velocity (robot frame) x, y; walking-to x, y, h;
// uptime; ball age.
#include <cstdint>
#include <optional>
#include <vector>

#include "touchline/python/runswift/types.hpp"

namespace touchline::python::runswift {

constexpr size_t kBroadcastBytes = 66;

/// A teammate's broadcast with what the SPL message part carries beside it.
struct Broadcast {
  BroadcastData data;
  bool fallen = false;
  bool penalised = false;
  float ball_age_s = -1; ///< s since the sender saw the ball; -1: never
};

std::vector<uint8_t> encode_broadcast(const Broadcast& broadcast);
/// Nothing for bytes that are not a broadcast of this layout (another team's format, junk).
std::optional<Broadcast> decode_broadcast(const std::vector<uint8_t>& bytes);

} // namespace touchline::python::runswift
