#include "touchline/behaviour/skills/supporter.hpp"

#include "touchline/behaviour/skills/ball.hpp"

namespace touchline::behaviour::skills {

using namespace api;

FieldPoint midfielderTarget(float ballX, float ballY, float robotY) {
  if (ballX >= MID_FAR_BALL_X) return {MID_FAR_X, 0.f};
  if (ballX >= MID_PARALLEL_BALL_X) {
    if (robotY < ballY) return {ballX, ballY - MID_PARALLEL_Y};
    return {ballX, ballY + MID_PARALLEL_Y};
  }
  const float distFromBall = (MID_PARALLEL_BALL_X - ballX) * MID_MAX_DIST_FROM_BALL / MID_DIST_SPAN;
  return {ballX + distFromBall, robotY};
}

FieldPoint defenderTarget(float ballX, float ballY) {
  if (ballX <= DEF_DEEP_BALL_X) return {DEF_DEEP_X, 0.f};
  float x;
  if (ballX > -DEF_DIST_FROM_BALL) {
    x = DEF_MAX_X;
  } else {
    x = ballX + DEF_DIST_FROM_BALL;
  }
  return {x, ballY * (x - OWN_GOAL_X) / (ballX - OWN_GOAL_X)};
}

FieldPoint supporterTarget(float x, float y, float ballX, float ballY, float robotY) {
  FieldPoint p = avoidShootingPath(x, y, ballX, ballY, robotY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y);
  p = clampToField(p.x, p.y);
  return clampOutOfOwnBox(p.x, p.y);
}

Supporter::Supporter(float homeX, float homeY) : goToPose_(0.f, 0.f, 0.f, true), goHome_(homeX, homeY, 0.f) {}

ActionCommand::All Supporter::tick(const Blackboard& blackboard) {
  if (blackboard.localisation.ballLostCount > SUPPORTER_BALL_LOST_FRAMES) return goHome_.tick(blackboard);
  const AbsCoord ball = blackboard.localisation.ballPos;
  const float robotY = blackboard.localisation.robotPos.y;
  const FieldPoint raw = target(ball.x, ball.y, robotY);
  const FieldPoint safe = supporterTarget(raw.x, raw.y, ball.x, ball.y, robotY);
  goToPose_.setTarget(safe.x, safe.y, 0.f);
  return goToPose_.tick(blackboard);
}

FieldPoint Midfielder::target(float ballX, float ballY, float robotY) const {
  return midfielderTarget(ballX, ballY, robotY);
}

FieldPoint Defender::target(float ballX, float ballY, float) const { return defenderTarget(ballX, ballY); }

} // namespace touchline::behaviour::skills
