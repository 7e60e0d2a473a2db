#pragma once
#include <cmath>

namespace touchline {

constexpr float kPi = 3.14159265358979323846f;

/// Wraps an angle into [-pi, pi).
inline float normalise_angle(float a) {
  a = std::fmod(a + kPi, 2 * kPi);
  if (a < 0) a += 2 * kPi;
  return a - kPi;
}

inline float deg2rad(float d) { return d * kPi / 180.f; }

} // namespace touchline
