#pragma once
// Geometry types of the robot API, as the robot code uses them: millimetres and radians,
// field origin at the centre, +x towards the opponent goal, +y left, theta counter-clockwise.
#include <cmath>

namespace touchline::api {

constexpr float kPi = 3.14159265358979323846f;

/// Wraps an angle into [-pi, pi).
inline float normaliseTheta(float theta) {
  theta = std::fmod(theta + kPi, 2 * kPi);
  if (theta < 0) theta += 2 * kPi;
  return theta - kPi;
}

/// An absolute (field) or odometry pose.
struct AbsCoord {
  float x = 0;     ///< mm
  float y = 0;     ///< mm
  float theta = 0; ///< rad
};

/// A robot-relative position: distance and heading from the robot's body.
struct RRCoord {
  float distance = 0; ///< mm
  float heading = 0;  ///< rad, + left of straight ahead
  float x() const { return distance * std::cos(heading); }
  float y() const { return distance * std::sin(heading); }
};

/// Robot-relative coordinates of an absolute point seen from `robot`.
inline RRCoord toRobotRelative(const AbsCoord& robot, float x, float y) {
  const float dx = x - robot.x, dy = y - robot.y;
  return {std::hypot(dx, dy), normaliseTheta(std::atan2(dy, dx) - robot.theta)};
}

} // namespace touchline::api
