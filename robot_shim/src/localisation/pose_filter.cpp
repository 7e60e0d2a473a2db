#include "touchline/robot/localisation/pose_filter.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Dense>

#include "touchline/robot_api/geometry.hpp"

namespace touchline::robot::localisation {

namespace {
using Matrix3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
using Matrix23 = Eigen::Matrix<double, 2, 3>;

Eigen::Map<Matrix3> as_matrix(PoseCovariance& c) { return Eigen::Map<Matrix3>(c.data()); }

double sq(double v) { return v * v; }

/// The range/bearing a landmark would have from a pose, and its Jacobian.
struct Linearisation {
  Eigen::Vector2d predicted;  ///< range mm, bearing rad
  Matrix23 h;
};

std::optional<Linearisation> linearise(const FieldPoint& landmark, const Eigen::Vector3d& pose, double min_range_mm) {
  const double dx = landmark.x_mm - pose(0), dy = landmark.y_mm - pose(1);
  const double q = dx * dx + dy * dy;
  const double range = std::sqrt(q);
  if (range < min_range_mm) return std::nullopt;
  Linearisation l;
  l.predicted << range, api::wrapAngle<double>(std::atan2(dy, dx) - pose(2));
  l.h << -dx / range, -dy / range, 0.0,
         dy / q, -dx / q, -1.0;
  return l;
}

/// z - predicted, the bearing wrapped: a landmark seen at +3.1 rad and predicted at -3.1
/// is 0.08 rad off, not 6.2.
Eigen::Vector2d measurement_difference(const Eigen::Vector2d& z, const Eigen::Vector2d& predicted) {
  return {z(0) - predicted(0), api::wrapAngle<double>(z(1) - predicted(1))};
}
} // namespace

PoseCovariance diagonal_covariance(double sigma_x_mm, double sigma_y_mm, double sigma_theta_rad) {
  return {sq(sigma_x_mm), 0, 0, 0, sq(sigma_y_mm), 0, 0, 0, sq(sigma_theta_rad)};
}

OdometryDelta odometry_delta(const Pose2D& before, const Pose2D& after) {
  const double dx = static_cast<double>(after.x_mm) - before.x_mm;
  const double dy = static_cast<double>(after.y_mm) - before.y_mm;
  const double c = std::cos(static_cast<double>(before.theta_rad)), s = std::sin(static_cast<double>(before.theta_rad));
  // Rotate the odometry-frame displacement into the robot frame at `before`.
  return {c * dx + s * dy, -s * dx + c * dy,
          api::wrapAngle<double>(static_cast<double>(after.theta_rad) - before.theta_rad)};
}

PoseFilter::PoseFilter(FieldMap field, PoseFilterDef def, const Pose2D& initial)
    : field_(field), def_(def) {
  reset(initial);
}

void PoseFilter::reset(const Pose2D& pose, const PoseCovariance& covariance) {
  mean_ = {pose.x_mm, pose.y_mm, api::wrapAngle<double>(pose.theta_rad)};
  covariance_ = covariance;
  rejections_in_a_row_ = 0;
  heading_votes_.clear();
}

void PoseFilter::reset(const Pose2D& pose) {
  reset(pose, diagonal_covariance(def_.initial_sigma_xy_mm, def_.initial_sigma_xy_mm, def_.initial_sigma_theta_rad));
}

void PoseFilter::predict(const OdometryDelta& delta) {
  for (HeadingVote& v : heading_votes_) ++v.age;
  heading_votes_.erase(std::remove_if(heading_votes_.begin(), heading_votes_.end(),
                                      [&](const HeadingVote& v) { return v.age > def_.heading_jump_window; }),
                       heading_votes_.end());
  const double theta = mean_[2];
  const double c = std::cos(theta), s = std::sin(theta);
  mean_[0] += c * delta.dx_mm - s * delta.dy_mm;
  mean_[1] += s * delta.dx_mm + c * delta.dy_mm;
  mean_[2] = api::wrapAngle<double>(theta + delta.dtheta_rad);

  // Jacobian of the motion with respect to the state: only the heading moves x and y.
  Matrix3 f = Matrix3::Identity();
  f(0, 2) = -s * delta.dx_mm - c * delta.dy_mm;
  f(1, 2) = c * delta.dx_mm - s * delta.dy_mm;
  // The odometry noise lives in the robot frame; rotate it into the field frame.
  Matrix3 g = Matrix3::Identity();
  g(0, 0) = c;
  g(0, 1) = -s;
  g(1, 0) = s;
  g(1, 1) = c;
  const double walked = std::hypot(delta.dx_mm, delta.dy_mm);
  const double turned = std::fabs(delta.dtheta_rad);
  const double var_xy = def_.odo_xy_var_per_mm * walked + def_.odo_xy_var_per_call;
  const double var_theta =
      delta.turn_from_gyro
          ? def_.gyro_theta_var_per_rad * turned + def_.gyro_theta_var_per_mm * walked + def_.gyro_theta_var_per_call
          : def_.odo_theta_var_per_rad * turned + def_.odo_theta_var_per_mm * walked + def_.odo_theta_var_per_call;
  const Eigen::Vector3d q_robot(var_xy, var_xy, var_theta);

  auto p = as_matrix(covariance_);
  const Matrix3 predicted = f * p * f.transpose() + g * q_robot.asDiagonal() * g.transpose();
  p = 0.5 * (predicted + predicted.transpose());
}

UpdateResult PoseFilter::update(const Observation& observation) {
  const auto landmark = field_.landmark(observation.kind, observation.id);
  const double range = observation.distance_mm;
  if (!landmark || range < def_.min_range_mm) {
    ++stats_.ignored;
    return UpdateResult::kIgnored;
  }
  const Eigen::Vector3d prior(mean_[0], mean_[1], mean_[2]);
  const auto at_prior = linearise(*landmark, prior, def_.min_range_mm);
  if (!at_prior) {  // the Jacobian blows up on top of the landmark
    ++stats_.ignored;
    return UpdateResult::kIgnored;
  }
  const Eigen::Vector2d z(range, observation.heading_rad);
  const double range_sigma = def_.range_sigma_mm + def_.range_sigma_per_mm * range;
  const double bearing_sigma = def_.bearing_sigma_rad + def_.bearing_sigma_per_mm * range;
  const Eigen::Matrix2d r = Eigen::Vector2d(sq(range_sigma), sq(bearing_sigma)).asDiagonal();
  auto p = as_matrix(covariance_);

  // Gate on the innovation at the prior.
  const Eigen::Vector2d innovation = measurement_difference(z, at_prior->predicted);
  const Eigen::Matrix2d s = at_prior->h * p * at_prior->h.transpose() + r;
  const double mahalanobis_sq = innovation.dot(s.inverse() * innovation);
  stats_.last_mahalanobis_sq = mahalanobis_sq;
  if (!(mahalanobis_sq <= def_.gate_mahalanobis_sq)) {  // also rejects NaN
    ++stats_.rejected;
    if (vote_heading_jump(sq(innovation(0)) / s(0, 0), innovation(1), s(1, 1), range,
                          static_cast<int>(observation.kind) * 256 + observation.id))
      return UpdateResult::kRejected;
    if (++rejections_in_a_row_ >= def_.max_rejections_in_a_row) {
      // Everything disagrees with the estimate: trust it less so the landmarks can win.
      p += Eigen::Vector3d(sq(def_.lost_sigma_xy_mm), sq(def_.lost_sigma_xy_mm), sq(def_.lost_sigma_theta_rad))
               .asDiagonal();
      ++stats_.inflations;
      rejections_in_a_row_ = 0;
    }
    return UpdateResult::kRejected;
  }

  // Iterated EKF: re-linearise at the corrected pose (Gauss-Newton on the measurement).
  // A plain EKF linearises at the prior; for a landmark a few hundred millimetres away
  // seen from a pose half a metre off, that linearisation is so wrong that the filter
  // ends up confident in a wrong pose.
  // The covariance is updated with the last iteration's gain and Jacobian (a pair).
  Linearisation lin = *at_prior;
  Matrix23 h = lin.h;
  Eigen::Matrix<double, 3, 2> k = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Vector3d estimate = prior;
  for (int i = 0; i < std::max(1, def_.update_iterations); ++i) {
    h = lin.h;
    k = p * h.transpose() * (h * p * h.transpose() + r).inverse();
    Eigen::Vector3d from_prior = prior - estimate;
    from_prior(2) = api::wrapAngle<double>(from_prior(2));
    Eigen::Vector3d next = prior + k * (measurement_difference(z, lin.predicted) - h * from_prior);
    next(2) = api::wrapAngle<double>(next(2));
    const bool settled = (next.head<2>() - estimate.head<2>()).norm() < 1.0 &&
                         std::fabs(api::wrapAngle<double>(next(2) - estimate(2))) < 1e-3;
    estimate = next;
    if (settled) break;
    const auto relinearised = linearise(*landmark, estimate, def_.min_range_mm);
    if (!relinearised) break;  // stepped onto the landmark: keep this step
    lin = *relinearised;
  }
  mean_ = {estimate(0), estimate(1), estimate(2)};
  // Joseph form: stays symmetric positive semi-definite despite rounding.
  const Matrix3 i_kh = Matrix3::Identity() - k * h;
  const Matrix3 updated = i_kh * p * i_kh.transpose() + k * r * k.transpose();
  p = 0.5 * (updated + updated.transpose());

  ++stats_.accepted;
  rejections_in_a_row_ = 0;
  return UpdateResult::kAccepted;
}

bool PoseFilter::vote_heading_jump(double range_innovation_sq_over_var, double bearing_innovation_rad,
                                   double bearing_var, double range_mm, int landmark) {
  if (def_.heading_jump_votes <= 0 || range_mm < def_.heading_jump_min_range_mm) return false;
  if (!(range_innovation_sq_over_var <= def_.heading_jump_range_gate_sq)) return false; // the position is off too
  if (!(sq(bearing_innovation_rad) / bearing_var > def_.gate_mahalanobis_sq)) return false; // not the bearing that failed
  // Seen at bearing b where b' was predicted: the robot faces (b' - b) further round than believed.
  heading_votes_.push_back({-bearing_innovation_rad, 0, landmark});
  if (static_cast<int>(heading_votes_.size()) < def_.heading_jump_votes) return false;
  std::vector<double> errors;
  for (const HeadingVote& v : heading_votes_) errors.push_back(v.error_rad);
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2), errors.end());
  const double median = errors[errors.size() / 2];
  double sum = 0;
  int agreeing = 0;
  std::vector<int> landmarks;
  for (const HeadingVote& v : heading_votes_)
    if (std::fabs(api::wrapAngle<double>(v.error_rad - median)) <= def_.heading_jump_agree_rad) {
      sum += api::wrapAngle<double>(v.error_rad - median);
      ++agreeing;
      if (std::find(landmarks.begin(), landmarks.end(), v.landmark) == landmarks.end()) landmarks.push_back(v.landmark);
    }
  if (agreeing < def_.heading_jump_votes || static_cast<int>(landmarks.size()) < def_.heading_jump_landmarks)
    return false;
  mean_[2] = api::wrapAngle<double>(mean_[2] + median + sum / agreeing);
  // The heading is known again to the votes' spread; the position's correlation with the
  // old heading is void, and the position itself was dragged while the heading was wrong.
  auto p = as_matrix(covariance_);
  p(0, 2) = p(2, 0) = p(1, 2) = p(2, 1) = 0;
  p(2, 2) = sq(def_.heading_jump_sigma_theta_rad);
  p(0, 0) += sq(def_.heading_jump_sigma_xy_mm);
  p(1, 1) += sq(def_.heading_jump_sigma_xy_mm);
  heading_votes_.clear();
  rejections_in_a_row_ = 0;
  ++stats_.heading_jumps;
  return true;
}

Pose2D PoseFilter::pose() const {
  return {static_cast<float>(mean_[0]), static_cast<float>(mean_[1]),
          api::wrapAngle(static_cast<float>(mean_[2]))};
}

double PoseFilter::sigma_x_mm() const { return std::sqrt(covariance_[0]); }
double PoseFilter::sigma_y_mm() const { return std::sqrt(covariance_[4]); }
double PoseFilter::sigma_theta_rad() const { return std::sqrt(covariance_[8]); }

} // namespace touchline::robot::localisation
