#include "touchline/sim/camera.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::sim {

float max_camera_distance(const CameraDef& camera, float pitch_rad) {
  const float pitch = std::clamp(pitch_rad, camera.min_pitch_rad, camera.max_pitch_rad);
  return (camera.max_pitch_rad - pitch) * camera.range_span_mm / (camera.max_pitch_rad - camera.min_pitch_rad) +
         camera.near_range_mm;
}

std::optional<Sighting> sight(const CameraDef& camera, const Pose2D& body, float head_yaw_rad, float head_pitch_rad,
                              float x_mm, float y_mm) {
  const float dx = x_mm - body.x_mm, dy = y_mm - body.y_mm;
  const float distance = std::hypot(dx, dy);
  if (distance >= max_camera_distance(camera, head_pitch_rad)) return std::nullopt;
  const float half_view = camera.field_of_view_rad / 2;
  const float head_angle = normalise_angle(body.theta_rad + head_yaw_rad);
  // The thesis compares raw angles; normalising the difference keeps objects visible
  // across the -pi/pi seam.
  const float off_axis = normalise_angle(std::atan2(dy, dx) - head_angle);
  if (std::fabs(off_axis) >= half_view) return std::nullopt;
  Sighting s;
  s.distance_mm = distance;
  s.heading_rad = normalise_angle(off_axis + head_yaw_rad);
  s.image_x = (off_axis + half_view) / (2 * half_view);
  return s;
}

} // namespace touchline::sim
