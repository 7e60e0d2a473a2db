#pragma once
// Between the world's API (mm, field frame) and Box2D's (metres): the conversions and the
// pose of a body, shared by the world's source files (not part of its interface).
#include <box2d/box2d.h>

#include <cmath>

#include "touchline/angles.hpp"
#include "touchline/frame.hpp"

namespace touchline::sim::detail {

// Box2D is tuned for objects of 0.1-10 m, so the world runs in metres; the API is in mm.
inline float to_m(float mm) { return mm / 1000.f; }
inline float to_mm(float m) { return m * 1000.f; }
inline b2Vec2 to_m(float x_mm, float y_mm) { return b2Vec2(to_m(x_mm), to_m(y_mm)); }

/// `v` turned by `theta` rad.
inline b2Vec2 rotate(float theta, b2Vec2 v) {
  const float c = std::cos(theta), s = std::sin(theta);
  return b2Vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

/// Where `body` is, in mm and rad (normalised).
inline Pose2D pose_of(const b2Body& body) {
  const b2Vec2 p = body.GetPosition();
  return Pose2D{to_mm(p.x), to_mm(p.y), normalise_angle(body.GetAngle())};
}

} // namespace touchline::sim::detail
