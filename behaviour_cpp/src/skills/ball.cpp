#include "touchline/behaviour/skills/ball.hpp"

#include <cmath>

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

} // namespace touchline::behaviour::skills
