#include "touchline/behaviour/skills/robot_limits.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::behaviour::skills {

float clamp(float value, float low, float high) { return std::min(std::max(value, low), high); }

float clampTurn(float turn) { return clamp(turn, -MAX_TURN, MAX_TURN); }

WalkVelocity clampWalk(float forward, float left) {
  float scale = 1.f;
  const float maxForward = forward >= 0.f ? MAX_FORWARD : MAX_BACKWARD;
  if (std::fabs(forward) > maxForward) scale = maxForward / std::fabs(forward);
  if (std::fabs(left) * scale > MAX_LEFT) scale = MAX_LEFT / std::fabs(left);
  return {forward * scale, left * scale};
}

} // namespace touchline::behaviour::skills
