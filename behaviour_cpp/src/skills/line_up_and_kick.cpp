#include "touchline/behaviour/skills/line_up_and_kick.hpp"

#include <algorithm>
#include <cmath>

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"

namespace touchline::behaviour::skills {

using namespace api;

float carrySpeed(float ballX) {
  return clamp(CARRY_SPEED + CARRY_CLOSING_GAIN * (ballX - KICK_BALL_X), CARRY_SPEED, MAX_FORWARD);
}

LineUpAndKick::LineUpAndKick(float goalX, float goalY, bool dribble, std::optional<float> power,
                             const std::optional<std::string>& policy, bool carry)
    : goalX_(goalX),
      goalY_(goalY),
      dribble_(dribble),
      power_(power.value_or(dribble ? DRIBBLE_POWER : KICK_POWER)),
      carry_(carry),
      goToBall_(goalX, goalY, BEHIND_BALL_DIST, policy) {}

ActionCommand::All LineUpAndKick::tick(const Blackboard& blackboard) {
  if (!ballRecentlySeen(blackboard)) {
    liningUp_ = false;
    return actioncommand::compose({}, actioncommand::stand());
  }
  const AbsCoord pos = blackboard.localisation.robotPos;
  const AbsCoord ball = blackboard.localisation.ballPos;
  const RRCoord ballRR = toRobotRelative(pos, ball.x, ball.y);
  const FieldPointExact aim = kickAim(ball.x, ball.y, goalX_, goalY_, BEHIND_BALL_DIST);
  const float aimError = normaliseTheta(
      std::atan2(static_cast<float>(aim.y) - ball.y, static_cast<float>(aim.x) - ball.x) - pos.theta);
  seen_ = remember(seen_, blackboard);
  float nearest = CONTEST_DIST, nearestY = 0.f; // the obstacle nearest the ball within CONTEST_DIST
  for (const Obstacle& o : obstacles(blackboard, seen_)) {
    const float dist = std::hypot(o.x - ballRR.x(), o.y - ballRR.y());
    if (dist < nearest) {
      nearest = dist;
      nearestY = o.y;
    }
  }
  contested_ = nearest < CONTEST_DIST;
  const float awaySide = nearestY > ballRR.y() ? -1.f : 1.f; // sideways away from that obstacle: + left
  const bool far = std::hypot(goalX_ - ball.x, goalY_ - ball.y) > KICK_FAR_DIST;
  aimTolerance_ = contested_ ? CONTEST_ANGLE_TOLERANCE : far ? KICK_FAR_ANGLE_TOLERANCE : KICK_ANGLE_TOLERANCE;
  updateLiningUp(ballRR, aimError);
  if (!liningUp_) {
    stalledFrames_ = sidestepFrames_ = 0;
    return goToBall_.tick(blackboard);
  }
  if (sidestepFrames_ > 0) { // a stalled contest: step round the ball for a clear kick
    --sidestepFrames_;
    const WalkVelocity v = keepClear(blackboard, 0.f, sidestepLeft_);
    return actioncommand::compose(
        {}, actioncommand::walk(v.forward, v.left, clamp(TURN_GAIN * ballRR.heading, -LINE_UP_MAX_TURN, LINE_UP_MAX_TURN)));
  }
  if (contested_ && std::hypot(ball.x - stallBallX_, ball.y - stallBallY_) < STALL_BALL_MOVE) {
    if (++stalledFrames_ >= STALL_FRAMES) {
      stalledFrames_ = 0;
      sidestepFrames_ = SIDESTEP_FRAMES;
      sidestepLeft_ = awaySide * LINE_UP_MAX_SPEED;
    }
  } else {
    stalledFrames_ = 0;
    stallBallX_ = ball.x;
    stallBallY_ = ball.y;
  }
  if (carry_ && std::fabs(aimError) < CARRY_ANGLE && 0.f < ballRR.x() && ballRR.x() < CARRY_BALL_X &&
      std::fabs(ballRR.y()) < CARRY_BALL_Y) {
    const float dodge = contested_ ? awaySide * CONTEST_DODGE_SPEED : 0.f;
    const float left = clamp(LINE_UP_GAIN * ballRR.y() + dodge, -LINE_UP_MAX_SPEED, LINE_UP_MAX_SPEED);
    const float turn = clamp(TURN_GAIN * aimError, -LINE_UP_MAX_TURN, LINE_UP_MAX_TURN);
    const float speed = carrySpeed(ballRR.x());
    WalkVelocity v = keepClear(blackboard, speed, left);
    const float lean = std::min(CONTEST_LEAN_SPEED, speed);
    if (contested_ && v.forward < lean) v = keepInBounds(blackboard, lean, left); // into the contest, not away
    return actioncommand::compose({}, actioncommand::walk(v.forward, v.left, turn));
  }
  ActionCommand::Body body = lineUp(ballRR, aimError);
  if (body.actionType == ActionCommand::ActionType::WALK) {
    const WalkVelocity v = keepClear(blackboard, body.forward, body.left);
    body.forward = v.forward;
    body.left = v.left;
  }
  return actioncommand::compose({}, body);
}

void LineUpAndKick::updateLiningUp(const RRCoord& ballRR, float aimError) {
  if (liningUp_) {
    liningUp_ = ballRR.distance < LINE_UP_LEAVE_DIST && std::fabs(ballRR.heading) < LINE_UP_LEAVE_ANGLE &&
                std::fabs(aimError) < std::max(LINE_UP_LEAVE_ANGLE, aimTolerance_);
    return;
  }
  liningUp_ = ballRR.distance < LINE_UP_ENTER_DIST && std::fabs(ballRR.heading) < LINE_UP_ENTER_ANGLE &&
              std::fabs(aimError) < std::max({LINE_UP_ENTER_ANGLE, aimTolerance_, carry_ ? CARRY_ANGLE : 0.f});
  if (liningUp_) foot_ = ballRR.y() >= 0.f ? ActionCommand::Foot::LEFT : ActionCommand::Foot::RIGHT;
}

float LineUpAndKick::footY() const { return foot_ == ActionCommand::Foot::LEFT ? FOOT_OFFSET : -FOOT_OFFSET; }

ActionCommand::Body LineUpAndKick::lineUp(const RRCoord& ballRR, float aimError) const {
  const float xError = ballRR.x() - KICK_BALL_X;
  const float yError = ballRR.y() - footY();
  if (std::fabs(xError) < KICK_X_TOLERANCE && std::fabs(yError) < KICK_Y_TOLERANCE && std::fabs(aimError) < aimTolerance_) {
    if (dribble_) return actioncommand::dribble(power_, foot_);
    return actioncommand::kick(power_, foot_);
  }
  const float forward = clamp(LINE_UP_GAIN * xError, -LINE_UP_MAX_SPEED, LINE_UP_MAX_SPEED);
  const float left = clamp(LINE_UP_GAIN * yError, -LINE_UP_MAX_SPEED, LINE_UP_MAX_SPEED);
  const float turn = clamp(TURN_GAIN * aimError, -LINE_UP_MAX_TURN, LINE_UP_MAX_TURN);
  return actioncommand::walk(forward, left, turn);
}

} // namespace touchline::behaviour::skills
