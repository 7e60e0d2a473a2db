#include "touchline/robot/localisation_adapter.hpp"

#include <cmath>

namespace touchline::robot {

void LocalisationAdapter::tick(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  const bool back_from_penalty = was_penalised_ && !sense.penalised;
  was_penalised_ = sense.penalised;
  if (perfect_) {
    tick_perfect(sense, blackboard);
    return;
  }
  if (!localiser_) {
    localiser_.emplace(def_, sense.truth); // put down here by the team (or the referee)
  } else if (back_from_penalty) {
    localiser_->reset(sense.truth);
  }
  const api::AbsCoord& odometry = blackboard.motion.odometry;
  localiser_->frame(frame.utime, Pose2D{odometry.x, odometry.y, odometry.theta}, sense.seen);
  localiser_->write(blackboard.localisation);
}

void LocalisationAdapter::tick_perfect(const RobotSense& sense, api::Blackboard& blackboard) {
  auto& loc = blackboard.localisation;
  loc.robotPos = {sense.truth.x_mm, sense.truth.y_mm, sense.truth.theta_rad};
  const api::VisionBlackboard& vision = blackboard.vision;
  if (vision.ballSeen) {
    // Where the camera saw it, from the exact pose: only the camera's own noise remains.
    const float bearing = loc.robotPos.theta + vision.ball.heading;
    loc.ballPos = {loc.robotPos.x + vision.ball.distance * std::cos(bearing),
                   loc.robotPos.y + vision.ball.distance * std::sin(bearing), 0};
    loc.ballLostCount = 0;
  } else {
    ++loc.ballLostCount;
  }
  loc.ballPosRR = api::toRobotRelative(loc.robotPos, loc.ballPos.x, loc.ballPos.y);
  loc.teamBallPos = loc.ballPos;
}

} // namespace touchline::robot
