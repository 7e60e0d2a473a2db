#pragma once
// Angles for the world and the robot alike. The wrap itself is the robot API's (the
// bottom layer both sides share), so behaviours, robot and world wrap the same way.
#include <cmath>

#include "touchline/robot_api/geometry.hpp"

namespace touchline {

using api::kPi;

/// Wraps an angle into [-pi, pi) (api::wrapAngle).
inline float normalise_angle(float a) { return api::wrapAngle(a); }

/// Heading of a body standing on two feet headed a_rad and b_rad: the bisector of the
/// shorter arc between them, in [-pi, pi). The body frame of the frame contract
/// (frame.hpp's FootMotion): the walk and the world must agree on it to the bit.
inline float mean_heading(float a_rad, float b_rad) {
  return normalise_angle(a_rad + 0.5f * normalise_angle(b_rad - a_rad));
}

inline float deg2rad(float d) { return d * kPi / 180.f; }

} // namespace touchline
