#include "touchline/behaviour/skills/go_to_pose.hpp"

#include <cmath>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/field.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"

namespace touchline::behaviour::skills {

using namespace api;

GoToPose::GoToPose(float x, float y, float theta, bool faceBall) : faceBall_(faceBall) {
  setTarget(x, y, theta);
}

void GoToPose::setTarget(float x, float y, float theta) {
  const FieldPoint target = clampToField(x, y, -FIELD_EDGE_SLACK); // behind a ball on a line, not off the field
  x_ = target.x;
  y_ = target.y;
  theta_ = theta;
}

ActionCommand::All GoToPose::tick(const Blackboard& blackboard) {
  const AbsCoord pos = blackboard.localisation.robotPos;
  const RRCoord toTarget = toRobotRelative(pos, x_, y_);
  const float error = turnError(blackboard, pos);
  updateArrived(toTarget.distance, error);
  if (arrived_) return actioncommand::compose({}, avoid_.stand(blackboard));
  updateNear(toTarget, error);
  ActionCommand::Body body;
  if (!near_) {
    body = forwardFirst(toTarget);
  } else if (std::fabs(error) > TURN_FIRST_ANGLE) {
    body = actioncommand::walk(0.f, 0.f, clampTurn(TURN_GAIN * error));
  } else {
    body = algorithm43(pos, error);
  }
  return actioncommand::compose({}, avoid_.tick(blackboard, body, toTarget.distance));
}

float GoToPose::turnError(const Blackboard& blackboard, const AbsCoord& pos) const {
  if (faceBall_) {
    const AbsCoord ball = blackboard.localisation.ballPos;
    return toRobotRelative(pos, ball.x, ball.y).heading;
  }
  return normaliseTheta(theta_ - pos.theta);
}

void GoToPose::updateArrived(float distance, float error) {
  if (arrived_) {
    arrived_ = distance < LEAVE_DIST && std::fabs(error) < LEAVE_ANGLE;
  } else {
    arrived_ = distance < ARRIVE_DIST && std::fabs(error) < ARRIVE_ANGLE;
  }
}

namespace {

/// Seconds Algorithm 4.3 needs: turn to the final heading (`error` away), then walk to the
/// target in that heading, at the walk's speed in the target's direction.
float directTime(const RRCoord& toTarget, float error) {
  const float direction = toTarget.heading - error; // the target's bearing from the final heading
  const WalkVelocity v = clampWalk(1e4f * std::cos(direction), 1e4f * std::sin(direction));
  return std::fabs(error) / MAX_TURN + toTarget.distance / std::hypot(v.forward, v.left);
}

/// Seconds forward-first needs: face the target, walk forward, turn to the final heading.
float forwardFirstTime(const RRCoord& toTarget, float error) {
  const float turned = std::fabs(toTarget.heading) + std::fabs(normaliseTheta(error - toTarget.heading));
  return turned / MAX_TURN + toTarget.distance / MAX_FORWARD;
}

} // namespace

void GoToPose::updateNear(const RRCoord& toTarget, float error) {
  const float direct_s = directTime(toTarget, error);
  const float forward_first_s = forwardFirstTime(toTarget, error);
  if (near_) {
    near_ = toTarget.distance < FORWARD_FIRST_LEAVE_DIST || direct_s < forward_first_s + DIRECT_HYSTERESIS_S;
  } else {
    near_ = toTarget.distance < FORWARD_FIRST_DIST || direct_s + DIRECT_MARGIN_S < forward_first_s;
  }
}

float forwardFirstSpeedScale(float bearing) {
  const float facing = std::cos(bearing);
  return facing > 0.f ? facing * facing : 0.f;
}

ActionCommand::Body GoToPose::forwardFirst(const RRCoord& toTarget) const {
  const float turn = clampTurn(TURN_GAIN * toTarget.heading);
  const WalkVelocity v = clampWalk(WALK_GAIN * toTarget.distance, 0.f);
  return actioncommand::walk(v.forward * forwardFirstSpeedScale(toTarget.heading), v.left, turn);
}

ActionCommand::Body GoToPose::algorithm43(const AbsCoord& pos, float error) const {
  const float xDiff = x_ - pos.x;
  const float yDiff = y_ - pos.y;
  const float theta = kPi / 2 - pos.theta;
  const float fwd = xDiff * std::sin(theta) + yDiff * std::cos(theta);
  const float lft = xDiff * std::cos(theta) - yDiff * std::sin(theta);
  const WalkVelocity v = clampWalk(WALK_GAIN * fwd, WALK_GAIN * -lft);
  return actioncommand::walk(v.forward, v.left, clampTurn(TURN_GAIN * error));
}

} // namespace touchline::behaviour::skills
