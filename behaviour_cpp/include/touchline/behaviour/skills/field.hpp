#pragma once
// The field in the team's own frame (+x towards the opponent goal, own goal at x = -3000,
// SPL 2011: 6000 x 4000) and where supporters may stand: out of the own goal box, out of the
// ball's shooting path to the opponent goal, on the field. The port of
// behaviour_py/skills/field.py.

namespace touchline::behaviour::skills {

inline constexpr float OWN_GOAL_X = -3000.f;            ///< mm: the own goal line's centre
inline constexpr float FIELD_HALF_LENGTH = 3000.f;      ///< mm
inline constexpr float FIELD_HALF_WIDTH = 2000.f;       ///< mm
inline constexpr float FIELD_MARGIN = 200.f;            ///< mm: supporters' targets stay this far inside the lines
inline constexpr float FIELD_EDGE_SLACK = 50.f;         ///< mm: no target or walk takes a robot further beyond a line (the referee penalises 200)
inline constexpr float OWN_BOX_FRONT_X = -2400.f;       ///< mm: the own goal box is 600 deep ...
inline constexpr float OWN_BOX_HALF_WIDTH = 1100.f;     ///< mm: ... and 2200 wide
inline constexpr float BOX_MARGIN = 200.f;              ///< mm: supporters' targets stay this far out of the box
inline constexpr float SHOOTING_PATH_CLEARANCE = 500.f; ///< mm: supporters in front of the ball stay this far off the ball-goal line

/// A field point, mm.
struct FieldPoint {
  float x = 0;
  float y = 0;
};

/// (x, y) moved inside the field lines by `margin` (negative: to at most -margin beyond them).
FieldPoint clampToField(float x, float y, float margin = FIELD_MARGIN);
/// (x, y) moved forward out of the own goal box (grown by BOX_MARGIN) if it is in it.
FieldPoint clampOutOfOwnBox(float x, float y);
/// (x, y) moved sideways off the line from the ball to (goalX, goalY) when it lies in front
/// of the ball within SHOOTING_PATH_CLEARANCE of it; to the side the robot is on.
FieldPoint avoidShootingPath(float x, float y, float ballX, float ballY, float robotY, float goalX, float goalY);
float distance(float x0, float y0, float x1, float y1);

} // namespace touchline::behaviour::skills
