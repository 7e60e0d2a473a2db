#pragma once
// Line-of-sight blocking by robot bodies: seen from above, a robot is a disc about its
// body centre (the camera looks from the observer's body centre; heights are ignored).
#include "touchline/frame.hpp"

namespace touchline::sim {

/// Whether a robot body (a disc of `radius_mm` about `body`) hides the point (x, y) from
/// an eye at `eye`: the body is nearer the eye than the point and the line of sight
/// passes through the disc. A point inside the disc is hidden when seen from behind the
/// body. A body whose disc holds the eye itself (robots interpenetrating) hides nothing.
bool body_hides(const Pose2D& eye, const Pose2D& body, float radius_mm, float x_mm, float y_mm);

} // namespace touchline::sim
