#include "touchline/learning/pose_message.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::learning {

namespace {
constexpr uint8_t kTag0 = 'T', kTag1 = 'P';

void put(std::vector<uint8_t>& out, float value) {
  const auto v = static_cast<int16_t>(std::clamp(std::lround(value), -32767L, 32767L));
  const auto u = static_cast<uint16_t>(v);
  out.push_back(static_cast<uint8_t>(u & 0xff));
  out.push_back(static_cast<uint8_t>(u >> 8));
}

float get(const std::vector<uint8_t>& in, size_t at) {
  const auto u = static_cast<uint16_t>(in[at] | (in[at + 1] << 8));
  return static_cast<float>(static_cast<int16_t>(u));
}
} // namespace

std::vector<uint8_t> encode_pose_message(const api::AbsCoord& pose) {
  std::vector<uint8_t> out{kTag0, kTag1};
  put(out, pose.x);
  put(out, pose.y);
  put(out, 1000.f * pose.theta);
  return out;
}

std::optional<api::AbsCoord> decode_pose_message(const std::vector<uint8_t>& bytes) {
  if (bytes.size() != kPoseMessageBytes || bytes[0] != kTag0 || bytes[1] != kTag1) return std::nullopt;
  return api::AbsCoord{get(bytes, 2), get(bytes, 4), 1e-3f * get(bytes, 6)};
}

} // namespace touchline::learning
