#pragma once
// Geometry types of the robot API, as the robot code uses them: millimetres and radians,
// field origin at the centre, +x towards the opponent goal, +y left, theta counter-clockwise.
#include <cmath>

namespace touchline::api {

constexpr float kPi = 3.14159265358979323846f;

/// Wraps an angle into [-pi, pi), in the precision it is given: float for the robot code,
/// double for the learned policy's tiles and the localisation filters. The project's one
/// angle wrap (touchline/angles.hpp's normalise_angle is this too). fmod, as Python's
/// math.fmod in behaviour_py/skills/tile_policy.py: the two ports must pick the same tile.
template <typename Real>
Real wrapAngle(Real angle) {
  constexpr Real pi = static_cast<Real>(3.14159265358979323846);
  angle = std::fmod(angle + pi, 2 * pi);
  if (angle < 0) angle += 2 * pi;
  return angle - pi;
}

/// Wraps an angle into [-pi, pi) (runswift's name, float).
inline float normaliseTheta(float theta) { return wrapAngle(theta); }

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
