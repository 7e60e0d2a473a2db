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
inline constexpr float GOAL_MOUTH_AIM_DIST = 400.f;  ///< mm: a ball nearer a goal's line than this is aimed ...
/// mm: ... at the mouth's nearest point within this of its centre (the posts at 700, less
/// their 50 mm radius, the ball's 32.5 and a margin) ...
inline constexpr float GOAL_MOUTH_HALF_WIDTH = 600.f;
inline constexpr float GOAL_MOUTH_AIM_DEPTH = 200.f; ///< mm: ... this far inside the goal

bool ballRecentlySeen(const api::Blackboard& blackboard);

/// (x, y, theta): `behind` mm from `ball` on the line from the goal through the ball, facing the goal.
api::AbsCoord pointBehindBall(const api::AbsCoord& ball, float goalX, float goalY, float behind);

/// A field point in double, mm.
struct FieldPointExact {
  double x = 0, y = 0;
};

/// The goal point (goalX, goalY) on a goal line, as aimed at from a ball at (ballX, ballY): the
/// goal point itself, but within GOAL_MOUTH_AIM_DIST of that line the nearest point of the
/// mouth (within GOAL_MOUTH_HALF_WIDTH of the goal point) GOAL_MOUTH_AIM_DEPTH inside the
/// goal, moving there in proportion (all of the way at the line), so the aim never jumps.
/// A ball in the mouth on the line was aimed at the goal's centre, along the line, and the
/// spot behind it was at the post: the striker stood against the post for up to 28 s until
/// the referee restarted a stuck game (16 C++ matches: the ball still within 500 mm of a
/// goal line in front of a goal 3.3 % of the play; 1.7 % so). A goal point off the goal
/// lines (a pass) is returned as it is.
FieldPointExact goalMouthAim(double ballX, double ballY, double goalX, double goalY);

/// The point to aim the ball at (ballX, ballY) at, for the goal point (goalX, goalY): the
/// goal itself (goalMouthAim's point near the goal's line), unless standing `behind` mm
/// behind the ball facing it would put the robot more than FIELD_EDGE_SLACK beyond a line
/// (no walk takes it there: a ball on a line, where a ball out is put back, had strikers
/// standing beside it until someone else moved it).
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
