#include "touchline/robot/localisation/localiser.hpp"

namespace touchline::robot::localisation {

void write_localisation(const PoseFilter& pose, const BallFilter& ball, api::LocalisationBlackboard& out) {
  const Pose2D robot = pose.pose();
  out.robotPos = {robot.x_mm, robot.y_mm, robot.theta_rad};
  const FieldPoint b = ball.position();
  out.ballPos = {static_cast<float>(b.x_mm), static_cast<float>(b.y_mm), 0.f};
  out.ballPosRR = ball.relative_to(robot);
  out.ballLostCount = ball.lost_count();
  out.teamBallPos = out.ballPos;
  const FieldPoint v = ball.velocity();
  out.ballVel = {static_cast<float>(v.x_mm), static_cast<float>(v.y_mm), 0.f};
  for (size_t i = 0; i < out.robotPosCovariance.size(); ++i)
    out.robotPosCovariance[i] = static_cast<float>(pose.covariance()[i]);
  // The ball on the field is as uncertain as the track and the pose it is seen from.
  const std::array<double, 4> bc = ball.field_position_covariance(robot, pose.covariance());
  out.ballPosCovariance = {static_cast<float>(bc[0]), static_cast<float>(bc[1]), static_cast<float>(bc[2]),
                           static_cast<float>(bc[3])};
}

Localiser::Localiser(const LocalisationDef& def, const Pose2D& initial)
    : pose_(def.field, def.pose, initial), ball_(def.ball) {}

void Localiser::frame(int64_t utime_us, const Pose2D& odometry, const std::vector<Observation>& seen,
                      std::optional<float> gyro_turn_rad) {
  if (last_odometry_) {
    OdometryDelta moved = odometry_delta(*last_odometry_, odometry);
    if (gyro_turn_rad) {
      moved.dtheta_rad = *gyro_turn_rad;
      moved.turn_from_gyro = true;
    }
    pose_.predict(moved);
  }
  last_odometry_ = odometry;
  const double dt_s = last_utime_us_ ? static_cast<double>(utime_us - *last_utime_us_) * 1e-6 : 0.0;
  last_utime_us_ = utime_us;

  // Landmarks first, so the ball is placed from this frame's corrected pose; the ball, seen
  // from the pose, moves with a correction (BallFilter::move_with), not with odometry.
  const Pose2D before_landmarks = pose_.pose();
  for (const Observation& o : seen)
    if (is_landmark(o.kind)) pose_.update(o);
  ball_.move_with(before_landmarks, pose_.pose());
  ball_.predict(dt_s);
  for (const Observation& o : seen)
    if (o.kind == ObjectKind::kBall) ball_.update(o, pose_.pose());
}

} // namespace touchline::robot::localisation
