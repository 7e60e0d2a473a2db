#pragma once
// The robot's walk and head limits, and clamping to them: the port of
// behaviour_py/skills/robot_limits.py. Units: mm/s, rad/s, rad. Values match
// config/walk.ini and the MotionAdapter's HeadDef.

namespace touchline::behaviour::skills {

inline constexpr float MAX_FORWARD = 300.f;     ///< mm/s, walking forward
inline constexpr float MAX_BACKWARD = 200.f;    ///< mm/s, walking backward
inline constexpr float MAX_LEFT = 200.f;        ///< mm/s, sideways either way
inline constexpr float MAX_TURN = 1.5f;         ///< rad/s, either way

inline constexpr float MAX_HEAD_YAW = 2.08f;    ///< rad, either side
inline constexpr float MIN_HEAD_PITCH = -0.67f; ///< rad, looking up (pitch is + down)
inline constexpr float MAX_HEAD_PITCH = 0.51f;  ///< rad, looking down

float clamp(float value, float low, float high);
float clampTurn(float turn);

struct WalkVelocity {
  float forward = 0; ///< mm/s
  float left = 0;    ///< mm/s
};

/// Scales (forward, left) down into the walk limits, keeping its direction: clamping each
/// component alone would bend the path, the very error thesis 4.3 warns of.
WalkVelocity clampWalk(float forward, float left);

} // namespace touchline::behaviour::skills
