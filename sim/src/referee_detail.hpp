#pragma once
// Small helpers shared by the referee's source files (not part of its interface).
#include <cmath>
#include <cstdint>
#include <optional>

#include "touchline/angles.hpp"
#include "touchline/frame.hpp"

namespace touchline::sim::detail {

/// Seconds to whole microseconds, rounded: the referee times everything in integer
/// utime so that equal inputs give equal decisions.
inline int64_t to_us(float seconds) { return static_cast<int64_t>(std::llround(static_cast<double>(seconds) * 1e6)); }

/// A pose given from team 0's point of view (its half at -x, attacking +x), for `team`:
/// team 1's picture is team 0's turned 180 degrees about the centre spot.
inline Pose2D for_team(int team, const Pose2D& team0) {
  if (team == 0) return team0;
  return Pose2D{-team0.x_mm, -team0.y_mm, normalise_angle(team0.theta_rad + kPi)};
}

/// -1 or +1 (0 counts as +1).
inline float sign_of(float v) { return v < 0 ? -1.f : 1.f; }

/// The first of start_x, start_x + toward * step, start_x - toward * step, start_x + 2 *
/// toward * step, ... (at most max_steps each way) that `accept` takes, or nullopt: the
/// nearest free spot along a line, `toward` (+1 or -1) first on a tie.
template <class Accept>
std::optional<float> nearest_along_x(float start_x, float toward, float step, int max_steps, Accept accept) {
  for (int k = 0; k <= 2 * max_steps; ++k) {
    const float offset = static_cast<float>((k + 1) / 2) * (k % 2 == 1 ? 1.f : -1.f) * step;
    const float x = start_x + toward * offset;
    if (accept(x)) return x;
  }
  return std::nullopt;
}

} // namespace touchline::sim::detail
