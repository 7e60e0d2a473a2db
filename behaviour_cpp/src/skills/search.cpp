#include "touchline/behaviour/skills/search.hpp"

#include <cmath>
#include <tuple>
#include <utility>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/avoid.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/goalie.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"
#include "touchline/behaviour/skills/supporter.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

namespace touchline::behaviour::skills {

using namespace api;

FieldPoint homePosition(int role, const SupporterDef& supporters) {
  if (role == ROLE_DEFENDER) return {supporters.defHomeX, supporters.defHomeY};
  if (role == ROLE_MIDFIELDER) return {supporters.midHomeX, supporters.midHomeY};
  return {GOALIE_HOME_X, 0.f};
}

std::optional<FieldPoint> teamBall(int playerNumber, const std::vector<TeamMessage>& messages, int64_t utime) {
  std::optional<std::tuple<int, int, FieldPoint>> best; // (ball distance, player number, ball)
  for (const TeamMessage& message : messages) {
    if (message.playerNumber == playerNumber || utime - message.utime > MESSAGE_STALE_US) continue;
    const std::optional<TeamInfo> info = decodeMessage(message.data);
    if (!info || !info->ballSeen || info->penalised) continue;
    const FieldPoint ball{static_cast<float>(info->ballX), static_cast<float>(info->ballY)};
    const auto key = std::make_pair(info->ballDistance, info->playerNumber);
    if (!best || key < std::make_pair(std::get<0>(*best), std::get<1>(*best)))
      best = std::make_tuple(info->ballDistance, info->playerNumber, ball);
  }
  if (!best) return std::nullopt;
  return std::get<2>(*best);
}

AbsCoord teamBallTarget(int role, float ballX, float ballY, float robotY, const SupporterDef& supporters) {
  if (role == ROLE_STRIKER) {
    const FieldPointExact aim = kickAim(ballX, ballY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, BEHIND_BALL_DIST);
    return pointBehindBall(AbsCoord{ballX, ballY, 0.f}, static_cast<float>(aim.x), static_cast<float>(aim.y),
                           BEHIND_BALL_DIST);
  }
  FieldPoint target = role == ROLE_DEFENDER ? defenderTarget(ballX, ballY, supporters)
                                            : midfielderTarget(ballX, ballY, robotY, supporters);
  target = supporterTarget(target.x, target.y, ballX, ballY, robotY);
  return AbsCoord{target.x, target.y, std::atan2(ballY - target.y, ballX - target.x)};
}

FieldPoint searchSpot(int role, int walk) {
  const int first = role == ROLE_STRIKER      ? STRIKER_FIRST_SPOT
                    : role == ROLE_MIDFIELDER ? MIDFIELDER_FIRST_SPOT
                                              : DEFENDER_FIRST_SPOT;
  const int spot = (first + walk) % SEARCH_SPOT_COUNT;
  const float sign = spot < 2 ? 1.f : -1.f;
  return spot % 2 == 0 ? FieldPoint{sign * SEARCH_SPOT_X, 0.f} : FieldPoint{0.f, sign * SEARCH_SPOT_Y};
}

FieldPoint dropInSpot(float ballX, float ballY, int dropInTeam, int ourTeam) {
  const float sideX = ballX < 0.f ? -1.f : 1.f, sideY = ballY < 0.f ? -1.f : 1.f;
  const float lineY = sideY * (FIELD_HALF_WIDTH - THROW_IN_LINE_INSET);
  const float lineEndX = FIELD_HALF_LENGTH - THROW_IN_LINE_END;
  if (std::fabs(ballY) - FIELD_HALF_WIDTH > std::fabs(ballX) - FIELD_HALF_LENGTH) { // over a touchline
    const float setback = dropInTeam == ourTeam ? -DROP_IN_SETBACK : dropInTeam == 1 - ourTeam ? DROP_IN_SETBACK : 0.f;
    return {clamp(ballX + setback, -lineEndX, lineEndX), lineY};
  }
  const int attackers = ballX < 0.f ? 1 - ourTeam : ourTeam; // of the goal whose line it left
  return {dropInTeam == attackers ? 0.f : sideX * lineEndX, lineY};
}

void Search::updateDropIn(const Blackboard& blackboard) {
  const GameControllerBlackboard& gc = blackboard.gameController;
  const LocalisationBlackboard& localisation = blackboard.localisation;
  const bool seen = localisation.ballLostCount == 0;
  if (gc.dropInTime >= 0 && (lastDropInTime_ < 0 || gc.dropInTime < lastDropInTime_) && !seen)
    dropIn_ = dropInSpot(localisation.ballPos.x, localisation.ballPos.y, gc.dropInTeam, gc.team);
  lastDropInTime_ = gc.dropInTime;
  if (seen || gc.dropInTime < 0 || gc.dropInTime >= DROP_IN_FRESH_S) dropIn_.reset();
}

ActionCommand::Body Search::toBall(const Blackboard& blackboard, int role, FieldPoint ball) {
  const AbsCoord target = teamBallTarget(role, ball.x, ball.y, blackboard.localisation.robotPos.y, supporters_);
  ballPose_.setTarget(target.x, target.y, target.theta);
  return ballPose_.tick(blackboard).body;
}

std::optional<ActionCommand::Body> Search::tick(const Blackboard& blackboard, int role) {
  const AbsCoord pos = blackboard.localisation.robotPos;
  updateDropIn(blackboard);
  if (dropIn_) return toBall(blackboard, role, *dropIn_);
  const int lost = blackboard.localisation.ballLostCount - SEARCH_TURN_FRAMES;
  if (lost <= 0) return std::nullopt;
  const RRCoord atFeet = blackboard.localisation.ballPosRR;
  if (atFeet.distance < BALL_AT_FEET_DIST) {
    const WalkVelocity away = keepClear(blackboard, -SEARCH_BACK_OFF_SPEED * std::cos(atFeet.heading),
                                        -SEARCH_BACK_OFF_SPEED * std::sin(atFeet.heading));
    return actioncommand::walk(away.forward, away.left, 0.f);
  }
  const GameControllerBlackboard& gc = blackboard.gameController;
  if (const auto ball = teamBall(gc.playerNumber, blackboard.receiver.messages, blackboard.utime))
    return toBall(blackboard, role, *ball);
  const int cycle = (lost - 1) / SEARCH_CYCLE_FRAMES;
  const int frame = (lost - 1) % SEARCH_CYCLE_FRAMES;
  if (role != ROLE_STRIKER && cycle == 0) {
    const FieldPoint home = homePosition(role, supporters_);
    if (frame >= SEARCH_TURN_LIMIT_FRAMES || distance(pos.x, pos.y, home.x, home.y) >= HOME_NEAR_DIST)
      return std::nullopt;
  }
  if (frame < SEARCH_TURN_LIMIT_FRAMES) {
    const float turn = blackboard.localisation.ballPosRR.heading >= 0.f ? SEARCH_TURN_SPEED : -SEARCH_TURN_SPEED;
    return actioncommand::walk(0.f, 0.f, turn);
  }
  const FieldPoint spot = searchSpot(role, role == ROLE_STRIKER ? cycle : cycle - 1);
  spotPose_.setTarget(spot.x, spot.y, 0.f);
  return spotPose_.tick(blackboard).body;
}

} // namespace touchline::behaviour::skills
