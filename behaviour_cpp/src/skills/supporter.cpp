#include "touchline/behaviour/skills/supporter.hpp"

#include <utility>

#include "touchline/behaviour/skills/ball.hpp"

namespace touchline::behaviour::skills {

using namespace api;

const SupporterDef& thesisSupporters() {
  static const SupporterDef thesis;
  return thesis;
}

const SupporterDef& tunedSupporters() {
  static const SupporterDef tuned = [] {
    SupporterDef d;
    // The defender plays closer behind the ball and up to the -500 line (the thesis: -1200),
    // so it meets the clearances in midfield: +0.50 goals a match over the thesis's numbers in
    // 40 C++ matches (README "Team results").
    d.defDistFromBall = -900.f;
    d.defMaxX = -500.f;
    return d;
  }();
  return tuned;
}

namespace {

/// The presets the skill parameter supporters=NAME picks from, the default first (as
/// supporter.py's SUPPORTER_DEFS).
const std::vector<std::pair<std::string, const SupporterDef*>>& presets() {
  static const std::vector<std::pair<std::string, const SupporterDef*>> all = {{"tuned", &tunedSupporters()},
                                                                              {"thesis", &thesisSupporters()}};
  return all;
}

} // namespace

const std::vector<std::string>& supporterDefNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> found;
    for (const auto& [name, def] : presets()) found.push_back(name);
    return found;
  }();
  return names;
}

const SupporterDef* supporterDef(const std::string& name) {
  for (const auto& [known, def] : presets())
    if (known == name) return def;
  return nullptr;
}

FieldPoint midfielderTarget(float ballX, float ballY, float robotY, const SupporterDef& d) {
  if (ballX >= d.midFarBallX) return {d.midFarX, 0.f};
  if (ballX >= d.midParallelBallX) {
    if (robotY < ballY) return {ballX, ballY - d.midParallelY};
    return {ballX, ballY + d.midParallelY};
  }
  // The distance grows linearly from 0 (ball at midParallelBallX) to midMaxDistFromBall (ball
  // on the own goal line).
  const float distFromBall = (d.midParallelBallX - ballX) * d.midMaxDistFromBall / (d.midParallelBallX - OWN_GOAL_X);
  return {ballX + distFromBall, robotY};
}

FieldPoint defenderTarget(float ballX, float ballY, const SupporterDef& d) {
  if (ballX <= d.defDeepBallX) return {d.defDeepX, 0.f};
  float x;
  if (ballX > -d.defDistFromBall) {
    x = d.defMaxX;
  } else {
    x = ballX + d.defDistFromBall;
  }
  return {x, ballY * (x - OWN_GOAL_X) / (ballX - OWN_GOAL_X)};
}

FieldPoint supporterTarget(float x, float y, float ballX, float ballY, float robotY) {
  FieldPoint p = avoidShootingPath(x, y, ballX, ballY, robotY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y);
  p = clampToField(p.x, p.y);
  return clampOutOfOwnBox(p.x, p.y);
}

Supporter::Supporter(const SupporterDef& supporters, FieldPoint home)
    : supporters_(supporters), goToPose_(0.f, 0.f, 0.f, true), goHome_(home.x, home.y, 0.f) {}

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
  return midfielderTarget(ballX, ballY, robotY, supporters_);
}

FieldPoint Defender::target(float ballX, float ballY, float) const { return defenderTarget(ballX, ballY, supporters_); }

} // namespace touchline::behaviour::skills
