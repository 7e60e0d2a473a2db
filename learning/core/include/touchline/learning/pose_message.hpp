#pragma once
// The team message every learner's robot sends: where it believes it is, so its teammates'
// observations can say where they are (through the league's radio: late, rate-bounded,
// sometimes lost, as a real team's would be). 8 bytes: the tag "TP", then x and y in mm
// and theta in milliradians, each a little-endian int16, in the sender's team frame.
#include <cstdint>
#include <optional>
#include <vector>

#include "touchline/robot_api/geometry.hpp"

namespace touchline::learning {

constexpr size_t kPoseMessageBytes = 8;

std::vector<uint8_t> encode_pose_message(const api::AbsCoord& pose);
/// The pose a message carries; nullopt for bytes that are not a pose message.
std::optional<api::AbsCoord> decode_pose_message(const std::vector<uint8_t>& bytes);

} // namespace touchline::learning
