#include "touchline/behaviour/skills/striker.hpp"

#include <cmath>

namespace touchline::behaviour::skills {

using namespace api;

bool shouldDribble(float ballX, float ballY) {
  return std::hypot(OPPONENT_GOAL_X - ballX, OPPONENT_GOAL_Y - ballY) < STRIKER_DRIBBLE_DIST;
}

Striker::Striker(const std::optional<std::string>& policy)
    : kick_(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, false, std::nullopt, policy, true),
      dribble_(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, true, std::nullopt, policy) {}

ActionCommand::All Striker::tick(const Blackboard& blackboard) {
  if (ballRecentlySeen(blackboard) && !kick_.liningUp() && !dribble_.liningUp()) {
    const AbsCoord ball = blackboard.localisation.ballPos;
    dribbling_ = shouldDribble(ball.x, ball.y);
  }
  if (dribbling_) return dribble_.tick(blackboard);
  return kick_.tick(blackboard);
}

} // namespace touchline::behaviour::skills
