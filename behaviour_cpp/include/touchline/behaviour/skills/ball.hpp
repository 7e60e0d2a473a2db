#pragma once
// What the skills ask about the ball: seen recently, and where to stand behind it. The
// port of behaviour_py/skills/ball.py.
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::behaviour::skills {

inline constexpr int BALL_LOST_FRAMES = 30;          ///< frames (1 s) without the ball before it counts as lost
inline constexpr float OPPONENT_GOAL_X = 3000.f;     ///< mm: the opponent goal's centre on a 6000 mm field
inline constexpr float OPPONENT_GOAL_Y = 0.f;        ///< mm
inline constexpr float BEHIND_BALL_DIST = 200.f;     ///< mm: robot centre to ball centre when lined up behind it
inline constexpr float MIN_GOAL_DIST = 1.f;          ///< mm: closer to the goal than this, aim along +x

bool ballRecentlySeen(const api::Blackboard& blackboard);

/// (x, y, theta): `behind` mm from `ball` on the line from the goal through the ball, facing the goal.
api::AbsCoord pointBehindBall(const api::AbsCoord& ball, float goalX, float goalY, float behind);

/// A field pose in double: mm, mm, rad.
struct FieldPose {
  double x = 0, y = 0, theta = 0;
};

/// pointBehindBall in double, operation for operation as Python computes it: the learned
/// walker's target, which must be the same bits in both ports for its policy to pick the
/// same action.
FieldPose pointBehindBallExact(const api::AbsCoord& ball, double goalX, double goalY, double behind);

} // namespace touchline::behaviour::skills
