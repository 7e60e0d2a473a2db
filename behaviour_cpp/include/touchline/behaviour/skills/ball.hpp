#pragma once
// What the skills ask about the ball: seen recently, where to aim it, and where to stand behind it. The
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

/// A field point in double, mm.
struct FieldPointExact {
  double x = 0, y = 0;
};

/// The point to aim the ball at (ballX, ballY) at, for the goal point (goalX, goalY): the
/// goal itself, unless standing `behind` mm behind the ball facing it would put the robot
/// more than FIELD_EDGE_SLACK beyond a line (no walk takes it there: a ball on a line, where
/// a ball out is put back, had strikers standing beside it until someone else moved it).
/// Then the aim turns towards that line's direction just enough for the robot to stand
/// FIELD_EDGE_SLACK beyond it, keeping its side of the goal: the point is the goal's distance
/// away along the turned aim. The touchlines first, then the goal lines. Near a corner no aim
/// keeps the robot within both (turning off the goal line put it beyond the touchline again,
/// facing along the goal line with the ball beside it, never lining up: 10 s stuck in the own
/// corner): then it aims out of the corner, standing equally far beyond both lines
/// (cornerAim). In double, operation for operation as Python computes it (the learned
/// walker's target is built on it).
FieldPointExact kickAim(double ballX, double ballY, double goalX, double goalY, double behind);

/// The unit aim (x, y) out of the corner nearest the ball that stands a robot `behind` mm
/// behind the ball equally far beyond both lines' slack: equal room left on both axes
/// (roomX - x = roomY - y, the rooms in units of `behind`). Where the room on one axis alone
/// allows an aim, this is the one-line aim, so the two meet where a corner starts.
FieldPointExact cornerAim(double ballX, double ballY, double behind);

/// The aim's `component` along one axis, limited so that standing `behind` mm behind the
/// ball (at `ball` on that axis) keeps the robot within +-limit on it.
double limitAim(double component, double ball, double limit, double behind);

/// A field pose in double: mm, mm, rad.
struct FieldPose {
  double x = 0, y = 0, theta = 0;
};

/// pointBehindBall in double, operation for operation as Python computes it: the learned
/// walker's target, which must be the same bits in both ports for its policy to pick the
/// same action.
FieldPose pointBehindBallExact(const api::AbsCoord& ball, double goalX, double goalY, double behind);

} // namespace touchline::behaviour::skills
