#include "touchline/behaviour/skills/actioncommand.hpp"

namespace touchline::behaviour::actioncommand {

AC::Body walk(float forward, float left, float turn, float speed) {
  AC::Body body;
  body.actionType = AC::ActionType::WALK;
  body.forward = forward;
  body.left = left;
  body.turn = turn;
  body.speed = speed;
  return body;
}

AC::Body stand() { return AC::Body{}; }

namespace {
AC::Body footAction(AC::ActionType actionType, float power, AC::Foot foot, float bend) {
  AC::Body body;
  body.actionType = actionType;
  body.power = power;
  body.foot = foot;
  body.bend = bend;
  return body;
}
} // namespace

AC::Body kick(float power, AC::Foot foot, float bend) {
  return footAction(AC::ActionType::KICK, power, foot, bend);
}

AC::Body dribble(float power, AC::Foot foot, float bend) {
  return footAction(AC::ActionType::DRIBBLE, power, foot, bend);
}

AC::Head head(float yaw, float pitch, bool isRelative, float yawSpeed, float pitchSpeed) {
  AC::Head request;
  request.yaw = yaw;
  request.pitch = pitch;
  request.isRelative = isRelative;
  request.yawSpeed = yawSpeed;
  request.pitchSpeed = pitchSpeed;
  return request;
}

AC::LED leds(int32_t chest) {
  AC::LED request;
  request.chest = chest;
  return request;
}

AC::All compose(const AC::Head& headRequest, const AC::Body& bodyRequest, const AC::LED& ledsRequest) {
  AC::All command;
  command.head = headRequest;
  command.body = bodyRequest;
  command.leds = ledsRequest;
  return command;
}

} // namespace touchline::behaviour::actioncommand
