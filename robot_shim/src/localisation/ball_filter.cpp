#include "touchline/robot/localisation/ball_filter.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "touchline/robot_api/geometry.hpp"

namespace touchline::robot::localisation {

namespace {
using Matrix4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;
using Matrix3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

double sq(double v) { return v * v; }

/// Until the first sighting: the ball could be anywhere on a field (sigma 3 m), at rest.
constexpr double kUnseenSigmaMm = 3000.0;
} // namespace

BallFilter::BallFilter(BallFilterDef def) : def_(def) {
  Eigen::Map<Matrix4> p(covariance_.data());
  p = Eigen::Vector4d(sq(kUnseenSigmaMm), sq(kUnseenSigmaMm), 0.0, 0.0).asDiagonal();
}

void BallFilter::predict(double dt_s) {
  ++lost_count_;
  if (dt_s <= 0) return;
  Eigen::Map<Eigen::Vector4d> x(state_.data());
  Eigen::Map<Matrix4> p(covariance_.data());

  // The mean slows as the world's ball does: speed minus decel * dt (not below zero),
  // then the linear damping.
  const double speed = std::hypot(x(2), x(3));
  const double damping = std::exp(-def_.linear_damping_per_s * dt_s);
  const double slowed = speed > 0 ? std::max(0.0, speed - def_.rolling_decel_mm_s2 * dt_s) / speed : 0.0;
  const double factor = slowed * damping;
  // Travel at the interval's mean velocity (linear in between).
  const double travel = dt_s * (1 + factor) / 2;
  x(0) += x(2) * travel;
  x(1) += x(3) * travel;
  x(2) *= factor;
  x(3) *= factor;

  // Covariance with the along-track Jacobian: the constant deceleration does not change
  // the speed's derivative along the motion (only across it), and using its mean factor
  // here would zero the velocity covariance of a ball at rest, which then could never
  // be seen to start rolling.
  Matrix4 f = Matrix4::Identity();
  f(0, 2) = f(1, 3) = dt_s;
  f(2, 2) = f(3, 3) = damping;
  // Piecewise-constant white acceleration (per axis: dt^4/4, dt^3/2; dt^3/2, dt^2).
  const double a2 = sq(def_.accel_sigma_mm_s2);
  Matrix4 q = Matrix4::Zero();
  q(0, 0) = q(1, 1) = a2 * std::pow(dt_s, 4) / 4;
  q(0, 2) = q(2, 0) = q(1, 3) = q(3, 1) = a2 * std::pow(dt_s, 3) / 2;
  q(2, 2) = q(3, 3) = a2 * sq(dt_s);
  const Matrix4 predicted = f * p * f.transpose() + q;
  p = 0.5 * (predicted + predicted.transpose());
}

bool BallFilter::update(const Observation& ball, const Pose2D& robot) {
  if (ball.kind != ObjectKind::kBall) return false;
  Eigen::Map<Eigen::Vector4d> x(state_.data());
  Eigen::Map<Matrix4> p(covariance_.data());

  // The sighting on the field: robot + range along (robot heading + bearing).
  const double range = ball.distance_mm;
  const double direction = api::wrapAngle<double>(static_cast<double>(robot.theta_rad) + ball.heading_rad);
  const double c = std::cos(direction), s = std::sin(direction);
  const Eigen::Vector2d z(robot.x_mm + range * c, robot.y_mm + range * s);

  // Its covariance: the camera's polar noise alone (the pose's error is the track's too).
  Eigen::Matrix2d j_polar;
  j_polar << c, -range * s,
             s, range * c;
  const double range_sigma = def_.range_sigma_mm + def_.range_sigma_per_mm * range;
  const Eigen::Matrix2d r_polar = Eigen::Vector2d(sq(range_sigma), sq(def_.bearing_sigma_rad)).asDiagonal();
  const Eigen::Matrix2d r = j_polar * r_polar * j_polar.transpose();

  const Eigen::Vector2d innovation = z - x.head<2>();
  const Eigen::Matrix2d s_mat = p.topLeftCorner<2, 2>() + r;
  const Eigen::Matrix2d s_inv = s_mat.inverse();
  const double mahalanobis_sq = innovation.dot(s_inv * innovation);

  ++stats_.updates;
  lost_count_ = 0;
  if (!seen_ || !(mahalanobis_sq <= def_.gate_mahalanobis_sq)) {
    // First sighting, or one the track cannot explain (a kick we did not see, a ball
    // put back): start over there, velocity unknown.
    if (seen_) ++stats_.reinitialisations;
    seen_ = true;
    x << z, 0.0, 0.0;
    p.setZero();
    p.topLeftCorner<2, 2>() = r;
    p.bottomRightCorner<2, 2>() = sq(def_.initial_speed_sigma_mm_s) * Eigen::Matrix2d::Identity();
    return true;
  }

  // H = [I 0]: the sighting measures the position.
  const Eigen::Matrix<double, 4, 2> k = p.leftCols<2>() * s_inv;
  x += k * innovation;
  Eigen::Matrix<double, 2, 4> h = Eigen::Matrix<double, 2, 4>::Zero();
  h(0, 0) = h(1, 1) = 1;
  const Matrix4 i_kh = Matrix4::Identity() - k * h;
  const Matrix4 updated = i_kh * p * i_kh.transpose() + k * r * k.transpose();
  p = 0.5 * (updated + updated.transpose());
  return true;
}

void BallFilter::move_with(const Pose2D& from, const Pose2D& to) {
  if (!seen_) return;
  // The rigid motion taking `from` to `to`: rotate by the heading change about `from`,
  // then shift by the position change.
  const double turn = api::wrapAngle<double>(static_cast<double>(to.theta_rad) - from.theta_rad);
  const Eigen::Rotation2Dd rotation(turn);
  const Eigen::Vector2d from_xy(from.x_mm, from.y_mm), to_xy(to.x_mm, to.y_mm);
  Eigen::Map<Eigen::Vector4d> x(state_.data());
  Eigen::Map<Matrix4> p(covariance_.data());
  x.head<2>() = to_xy + rotation * (Eigen::Vector2d(x.head<2>()) - from_xy);
  x.tail<2>() = rotation * Eigen::Vector2d(x.tail<2>());
  Matrix4 rotate = Matrix4::Zero();
  rotate.topLeftCorner<2, 2>() = rotation.toRotationMatrix();
  rotate.bottomRightCorner<2, 2>() = rotation.toRotationMatrix();
  const Matrix4 moved = rotate * p * rotate.transpose();
  p = 0.5 * (moved + moved.transpose());
}

api::RRCoord BallFilter::relative_to(const Pose2D& robot) const {
  return api::toRobotRelative({robot.x_mm, robot.y_mm, robot.theta_rad}, static_cast<float>(state_[0]),
                              static_cast<float>(state_[1]));
}

double BallFilter::position_sigma_mm() const {
  const Eigen::Map<const Matrix4> p(covariance_.data());
  return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(p.topLeftCorner<2, 2>()).eigenvalues().maxCoeff());
}

std::array<double, 4> BallFilter::field_position_covariance(const Pose2D& robot,
                                                             const PoseCovariance& robot_covariance) const {
  // The ball at (robot + offset) moves with the robot's position, and with its heading by
  // the offset turned a right angle: J = [1 0 -dy; 0 1 dx].
  const double dx = state_[0] - robot.x_mm, dy = state_[1] - robot.y_mm;
  Eigen::Matrix<double, 2, 3> j_pose;
  j_pose << 1, 0, -dy,
            0, 1, dx;
  const Eigen::Map<const Matrix3> robot_p(robot_covariance.data());
  const Eigen::Map<const Matrix4> p(covariance_.data());
  Eigen::Matrix2d field = p.topLeftCorner<2, 2>() + j_pose * robot_p * j_pose.transpose();
  field = 0.5 * (field + field.transpose());
  return {field(0, 0), field(0, 1), field(1, 0), field(1, 1)};
}

} // namespace touchline::robot::localisation
