#pragma once
// Angles for the world and the robot alike. The wrap itself is the robot API's (the
// bottom layer both sides share), so behaviours, robot and world wrap the same way.
#include <cmath>

#include "touchline/robot_api/geometry.hpp"

namespace touchline {

using api::kPi;

/// Wraps an angle into [-pi, pi) (api::wrapAngle).
inline float normalise_angle(float a) { return api::wrapAngle(a); }

inline float deg2rad(float d) { return d * kPi / 180.f; }

} // namespace touchline
