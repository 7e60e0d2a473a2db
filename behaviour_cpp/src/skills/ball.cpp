#include "touchline/behaviour/skills/ball.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/behaviour/skills/field.hpp"

namespace touchline::behaviour::skills {

bool ballRecentlySeen(const api::Blackboard& blackboard) {
  return blackboard.localisation.ballLostCount <= BALL_LOST_FRAMES;
}

api::AbsCoord pointBehindBall(const api::AbsCoord& ball, float goalX, float goalY, float behind) {
  const float dx = goalX - ball.x;
  const float dy = goalY - ball.y;
  const float dist = std::hypot(dx, dy);
  float dirX = 1.f, dirY = 0.f;
  if (dist >= MIN_GOAL_DIST) {
    dirX = dx / dist;
    dirY = dy / dist;
  }
  return {ball.x - behind * dirX, ball.y - behind * dirY, std::atan2(dirY, dirX)};
}

FieldPose pointBehindBallExact(const api::AbsCoord& ball, double goalX, double goalY, double behind) {
  const double dx = goalX - double{ball.x};
  const double dy = goalY - double{ball.y};
  const double dist = std::sqrt(dx * dx + dy * dy); // as ball.py: not hypot, whose last bit may differ
  double dirX = 1.0, dirY = 0.0;
  if (dist >= MIN_GOAL_DIST) {
    dirX = dx / dist;
    dirY = dy / dist;
  }
  return {double{ball.x} - behind * dirX, double{ball.y} - behind * dirY, std::atan2(dirY, dirX)};
}

FieldPointExact goalMouthAim(double ballX, double ballY, double goalX, double goalY) {
  if (std::abs(goalX) != double{FIELD_HALF_LENGTH}) return {goalX, goalY};
  const double share = std::clamp(1.0 - std::abs(goalX - ballX) / double{GOAL_MOUTH_AIM_DIST}, 0.0, 1.0);
  if (share == 0.0) return {goalX, goalY}; // the same bits as before it, far from the line
  const double halfWidth = double{GOAL_MOUTH_HALF_WIDTH};
  const double mouthY = std::clamp(ballY, goalY - halfWidth, goalY + halfWidth);
  return {goalX + std::copysign(double{GOAL_MOUTH_AIM_DEPTH} * share, goalX), goalY + (mouthY - goalY) * share};
}

FieldPointExact kickAim(double ballX, double ballY, double goalX, double goalY, double behind) {
  const FieldPointExact goal = goalMouthAim(ballX, ballY, goalX, goalY);
  goalX = goal.x;
  goalY = goal.y;
  const double dx = goalX - ballX;
  const double dy = goalY - ballY;
  const double dist = std::sqrt(dx * dx + dy * dy); // as pointBehindBallExact
  if (dist < MIN_GOAL_DIST) return {goalX, goalY};
  double dirX = dx / dist, dirY = dy / dist;
  bool turned = false;
  const double limitY = double{FIELD_HALF_WIDTH} + double{FIELD_EDGE_SLACK};
  const double limitedY = limitAim(dirY, ballY, limitY, behind);
  if (limitedY != dirY) {
    dirY = limitedY;
    dirX = std::copysign(std::sqrt(std::max(0.0, 1.0 - dirY * dirY)), dirX);
    turned = true;
  }
  const double limitedX = limitAim(dirX, ballX, double{FIELD_HALF_LENGTH} + double{FIELD_EDGE_SLACK}, behind);
  if (limitedX != dirX) {
    dirX = limitedX;
    dirY = std::copysign(std::sqrt(std::max(0.0, 1.0 - dirX * dirX)), dirY);
    turned = true;
    if (limitAim(dirY, ballY, limitY, behind) != dirY) { // the touchline again: a corner
      const FieldPointExact corner = cornerAim(ballX, ballY, behind);
      dirX = corner.x;
      dirY = corner.y;
    }
  }
  if (!turned) return {goalX, goalY};
  return {ballX + dist * dirX, ballY + dist * dirY};
}

FieldPointExact cornerAim(double ballX, double ballY, double behind) {
  const double roomX = (double{FIELD_HALF_LENGTH} + double{FIELD_EDGE_SLACK} - std::abs(ballX)) / behind;
  const double roomY = (double{FIELD_HALF_WIDTH} + double{FIELD_EDGE_SLACK} - std::abs(ballY)) / behind;
  const double c = std::clamp(roomX - roomY, -1.0, 1.0); // x - y of the aim
  const double x = (c + std::sqrt(2.0 - c * c)) / 2.0;
  return {-std::copysign(x, ballX), -std::copysign(x - c, ballY)};
}

double limitAim(double component, double ball, double limit, double behind) {
  const double standing = ball - behind * component;
  if (standing > limit) return std::clamp((ball - limit) / behind, -1.0, 1.0);
  if (standing < -limit) return std::clamp((ball + limit) / behind, -1.0, 1.0);
  return component;
}

} // namespace touchline::behaviour::skills
