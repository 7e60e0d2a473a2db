#pragma once
// The rate limit the motion generators share: the walk's acceleration limits and the head's
// joint speed both move a value towards its target by at most a fixed step per tick.
#include <algorithm>

namespace touchline::robot {

/// `current` moved towards `target` by at most `max_step` (>= 0), in the same units.
inline float approach(float current, float target, float max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

} // namespace touchline::robot
