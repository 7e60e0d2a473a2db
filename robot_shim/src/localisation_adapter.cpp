#include "touchline/robot/localisation_adapter.hpp"

#include <cmath>

#include "touchline/angles.hpp"

namespace touchline::robot {

namespace {

api::AbsCoord turned(const api::AbsCoord& c) { return {-c.x, -c.y, normalise_angle(c.theta + kPi)}; }

/// Team 1 sees the field turned by pi: its own goal at -x too.
void to_team_frame(api::LocalisationBlackboard& loc) {
  loc.robotPos = turned(loc.robotPos);
  loc.ballPos = turned(loc.ballPos);
  loc.ballPos.theta = 0;
  loc.teamBallPos = turned(loc.teamBallPos);
  loc.teamBallPos.theta = 0;
  loc.ballVel = {-loc.ballVel.x, -loc.ballVel.y, 0}; // a velocity turns with the frame
  // x and y change sign, theta does not: only the position-heading terms flip.
  for (size_t i : {2u, 5u, 6u, 7u}) loc.robotPosCovariance[i] = -loc.robotPosCovariance[i];
}

} // namespace

Pose2D to_team_frame(const Pose2D& world, int team) {
  if (team == 0) return world;
  return {-world.x_mm, -world.y_mm, normalise_angle(world.theta_rad + kPi)};
}

Pose2D to_world_frame(const Pose2D& own, int team) { return to_team_frame(own, team); } // a half turn is its own inverse

void LocalisationAdapter::tick(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  const bool back_from_penalty = was_penalised_ && !sense.penalised;
  was_penalised_ = sense.penalised;
  if (perfect_) {
    tick_perfect(sense, blackboard);
    return;
  }
  if (!localiser_) {
    localiser_.emplace(def_, sense.truth); // put down here by the team (or the referee)
  } else if (back_from_penalty || sense.placed) {
    localiser_->reset(sense.truth);
  }
  const api::AbsCoord& odometry = blackboard.motion.odometry;
  localiser_->frame(frame.utime, Pose2D{odometry.x, odometry.y, odometry.theta}, sense.seen, sense.gyro_turn_rad);
  localiser_->write(blackboard.localisation); // in the world frame: the landmark map is team 0's
  if (sense.id.team == 1) to_team_frame(blackboard.localisation);
}

void LocalisationAdapter::tick_perfect(const RobotSense& sense, api::Blackboard& blackboard) {
  auto& loc = blackboard.localisation;
  const Pose2D own = to_team_frame(sense.truth, sense.id.team);
  loc.robotPos = {own.x_mm, own.y_mm, own.theta_rad};
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
  loc.ballVel = {};            // no filter: no velocity estimate
  loc.robotPosCovariance = {}; // the pose is the truth
}

} // namespace touchline::robot
