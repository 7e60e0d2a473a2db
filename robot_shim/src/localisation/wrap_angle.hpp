#pragma once
// Angle wrapping in double precision for the filters (touchline/angles.hpp's is float).
#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::robot::localisation {

/// Wraps an angle into [-pi, pi).
inline double wrap_angle(double a) {
  constexpr double kTwoPi = 2 * 3.14159265358979323846;
  return a - kTwoPi * std::floor((a + kTwoPi / 2) / kTwoPi);
}

} // namespace touchline::robot::localisation
