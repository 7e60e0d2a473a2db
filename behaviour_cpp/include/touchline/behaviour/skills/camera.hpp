#pragma once
// The camera's visible range (thesis 2.2.5) and the head pitch that sees a distance: the
// port of behaviour_py/skills/camera.py.
// maxCameraDist = (elevation - MINPITCH) * 3000 / (MAXPITCH - MINPITCH) + 1000, with MINPITCH and
// MAXPITCH the head pitch joint limits and elevation = MINPITCH + MAXPITCH - pitch (the thesis's
// pitch grows looking up; the robot's is + down). The camera sees 60 degrees across.

namespace touchline::behaviour::skills {

inline constexpr float CAMERA_NEAR_RANGE = 1000.f;  ///< mm: visible range at MAX_HEAD_PITCH (fully down)
inline constexpr float CAMERA_RANGE_SPAN = 3000.f;  ///< mm: gained from MAX_ (down) to MIN_HEAD_PITCH (up)
inline constexpr float CAMERA_RANGE_MARGIN = 500.f; ///< mm: how far past the ball to see

/// maxCameraDist at head pitch `pitch` (rad), mm.
float visibleRange(float pitch);

/// The head pitch whose visible range reaches CAMERA_RANGE_MARGIN past `distance` (mm),
/// clamped to the joint limits: the thesis formula inverted.
float pitchToSee(float distance);

} // namespace touchline::behaviour::skills
