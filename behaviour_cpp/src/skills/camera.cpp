#include "touchline/behaviour/skills/camera.hpp"

#include "touchline/behaviour/skills/robot_limits.hpp"

namespace touchline::behaviour::skills {

float visibleRange(float pitch) {
  return (MAX_HEAD_PITCH - pitch) * CAMERA_RANGE_SPAN / (MAX_HEAD_PITCH - MIN_HEAD_PITCH) + CAMERA_NEAR_RANGE;
}

float pitchToSee(float distance) {
  const float wanted = distance + CAMERA_RANGE_MARGIN;
  const float pitch =
      MAX_HEAD_PITCH - (wanted - CAMERA_NEAR_RANGE) * (MAX_HEAD_PITCH - MIN_HEAD_PITCH) / CAMERA_RANGE_SPAN;
  return clamp(pitch, MIN_HEAD_PITCH, MAX_HEAD_PITCH);
}

} // namespace touchline::behaviour::skills
