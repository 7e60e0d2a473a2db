#pragma once
// The robot's localisation, once per camera frame: the pose filter follows the walk's
// odometry and the landmarks seen, the ball filter the ball seen from the estimated
// pose (moved with the pose when a landmark corrects it); together they write the
// Blackboard's localisation sub-blackboard.
#include <cstdint>
#include <optional>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/robot/localisation/ball_filter.hpp"
#include "touchline/robot/localisation/field_map.hpp"
#include "touchline/robot/localisation/pose_filter.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::robot::localisation {

struct LocalisationDef {
  FieldMap field;
  PoseFilterDef pose;
  BallFilterDef ball;
};

/// Writes robotPos, ballPos, ballPosRR (the ball estimate seen from the pose estimate),
/// ballLostCount, teamBallPos (our own ball until teammates share theirs), ballVel, the
/// pose's covariance and the ball's on the field (its track's and the pose's together).
void write_localisation(const PoseFilter& pose, const BallFilter& ball, api::LocalisationBlackboard& out);

class Localiser {
 public:
  /// `initial`: where the rules place the robot (its touchline spot at the start).
  Localiser(const LocalisationDef& def, const Pose2D& initial);

  /// One camera frame at simulated time `utime_us`: `odometry` is the walk's
  /// dead-reckoned pose now (MotionBlackboard::odometry; only its change since the last
  /// frame is used), `seen` the camera's observations this frame. With `gyro_turn_rad`
  /// (the inertial unit's turn since the last frame) the body turned by that, not by the
  /// odometry's turn: the walk knows only the steps it commanded, the gyro also feels a
  /// push or a foot caught on a post turning the robot.
  void frame(int64_t utime_us, const Pose2D& odometry, const std::vector<Observation>& seen,
             std::optional<float> gyro_turn_rad = std::nullopt);

  /// Re-places the robot at `pose` with the def's initial sigmas (e.g. returning from a
  /// penalty, where the rules say). The robot is there now: the next frame moves it by
  /// nothing (neither the odometry nor the gyro since the last frame, which may hold the
  /// referee turning it), and its odometry is the reference from then on.
  void reset(const Pose2D& pose) {
    pose_.reset(pose);
    last_odometry_.reset();
  }

  void write(api::LocalisationBlackboard& out) const { write_localisation(pose_, ball_, out); }

  const PoseFilter& pose_filter() const { return pose_; }
  const BallFilter& ball_filter() const { return ball_; }

 private:
  PoseFilter pose_;
  BallFilter ball_;
  std::optional<Pose2D> last_odometry_;
  std::optional<int64_t> last_utime_us_;
};

} // namespace touchline::robot::localisation
