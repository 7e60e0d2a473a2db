#pragma once
// The camera model of thesis 2.2.5 (Algorithm 2.3): a 60-degree field of view centred on
// the body heading plus head yaw, and a visible range that grows with head pitch:
// maxCameraDist = (pitch - MINPITCH) * 3000 / (MAXPITCH - MINPITCH) + 1000 mm.
#include <optional>

#include "touchline/frame.hpp"

namespace touchline::sim {

struct CameraDef {
  float field_of_view_rad = 1.0471976f; ///< 60 degrees, full width
  float min_pitch_rad = -0.67f;         ///< MINPITCH: head fully up (Nao joint limit)
  float max_pitch_rad = 0.51f;          ///< MAXPITCH: head fully down
  float near_range_mm = 1000.f;         ///< visible range at MINPITCH
  float range_span_mm = 3000.f;         ///< added range from MINPITCH to MAXPITCH
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
