#pragma once
// The camera model of thesis 2.2.5 (Algorithm 2.3): a 60-degree field of view centred on
// the body heading plus head yaw, and a visible range that grows as the head looks up:
// maxCameraDist = (elevation - MINPITCH) * 3000 / (MAXPITCH - MINPITCH) + 1000 mm. The
// thesis's pitch grows looking up; the robot API's pitch is + down (the Nao's HeadPitch),
// so it enters as elevation = MINPITCH + MAXPITCH - pitch: head fully up sees 4000 mm,
// fully down 1000 mm.
#include <optional>

#include "touchline/frame.hpp"

namespace touchline::sim {

struct CameraDef {
  float field_of_view_rad = 1.0471976f; ///< 60 degrees, full width
  float min_pitch_rad = -0.67f;         ///< head pitch joint limit, fully up (+ is down)
  float max_pitch_rad = 0.51f;          ///< head pitch joint limit, fully down
  float near_range_mm = 1000.f;         ///< visible range with the head fully down
  float range_span_mm = 3000.f;         ///< range gained from fully down to fully up
};

/// maxCameraDist for a head pitch (clamped to the joint range), mm.
float max_camera_distance(const CameraDef& camera, float pitch_rad);

/// An object the camera sees.
struct Sighting {
  float distance_mm = 0; ///< from the body centre
  float heading_rad = 0; ///< relative to the body heading, + left
  float image_x = 0;     ///< Algorithm 2.3's image coordinate: 0 at one edge of the view, 1 at the other
};

/// Algorithm 2.3: whether the point (x, y) is visible from `body` with the head at
/// (yaw, pitch), and where. Nothing if it is out of range or outside the field of view.
std::optional<Sighting> sight(const CameraDef& camera, const Pose2D& body, float head_yaw_rad, float head_pitch_rad,
                              float x_mm, float y_mm);

} // namespace touchline::sim
