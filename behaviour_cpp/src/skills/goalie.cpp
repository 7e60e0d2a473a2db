#include "touchline/behaviour/skills/goalie.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/behaviour/skills/ball.hpp"

namespace touchline::behaviour::skills {

using namespace api;

FieldPoint goalieTarget(float ballX, float ballY) {
  const float dx = ballX - OWN_GOAL_X;
  const float dy = ballY;
  const float dist = std::hypot(dx, dy);
  float x, y;
  if (dist < 1.f) {
    x = OWN_GOAL_X + GOALIE_GUARD_DIST;
    y = 0.f;
  } else {
    x = OWN_GOAL_X + GOALIE_GUARD_DIST * dx / dist;
    y = GOALIE_GUARD_DIST * dy / dist;
  }
  const float minX = OWN_GOAL_X + GOALIE_BOX_MARGIN;
  const float maxX = OWN_BOX_FRONT_X - GOALIE_BOX_MARGIN;
  const float maxY = OWN_BOX_HALF_WIDTH - GOALIE_BOX_MARGIN;
  return {std::min(std::max(x, minX), maxX), std::min(std::max(y, -maxY), maxY)};
}

bool ballNearBox(float ballX, float ballY, float margin) {
  return ballX < OWN_BOX_FRONT_X + margin && std::fabs(ballY) < OWN_BOX_HALF_WIDTH + margin;
}

Goalie::Goalie()
    : goToPose_(0.f, 0.f, 0.f, true),
      goHome_(GOALIE_HOME_X, 0.f, 0.f),
      clear_(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, /*dribble=*/false, std::nullopt, std::nullopt, /*carry=*/true) {}

ActionCommand::All Goalie::tick(const Blackboard& blackboard) {
  if (!ballRecentlySeen(blackboard)) {
    clearing_ = false;
    return goHome_.tick(blackboard);
  }
  const AbsCoord ball = blackboard.localisation.ballPos;
  if (clearing_) {
    clearing_ = ballNearBox(ball.x, ball.y, CLEAR_LEAVE_MARGIN);
  } else {
    clearing_ = ballNearBox(ball.x, ball.y, CLEAR_ENTER_MARGIN);
  }
  if (clearing_) return clear_.tick(blackboard);
  const FieldPoint target = goalieTarget(ball.x, ball.y);
  goToPose_.setTarget(target.x, target.y, 0.f);
  return goToPose_.tick(blackboard);
}

} // namespace touchline::behaviour::skills
