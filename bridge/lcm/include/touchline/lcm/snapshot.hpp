#pragma once
// Blackboard snapshots: a robot's Blackboard (as its behaviour saw it) and the request it
// returned, as a blackboard_snapshot_t, and back. The port corpus and lcm-spy use them.
#include <string>

#include "touchline/blackboard_snapshot_t.hpp"
#include "touchline/frame.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::transport {

/// "TL_BLACKBOARD_<team>_<player>"
std::string snapshot_channel(RobotId id);

blackboard_snapshot_t to_snapshot(const api::Blackboard& blackboard, RobotId id, int64_t frame);

/// The Blackboard the snapshot was taken from. Throws MalformedMessage (touchline/lcm/codec.hpp)
/// for a field out of range: ids, enums (action type, foot, kick phase, game state), frame
/// 0..kMaxFrame, negative counts, times or scores, numbers that are not finite.
api::Blackboard from_snapshot(const blackboard_snapshot_t& snapshot);

} // namespace touchline::transport
