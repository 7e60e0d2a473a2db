#pragma once
// Synthetic data for the localisation tests: a robot walking a path with exact motion,
// the noisy odometry it would report, and noisy camera observations computed from the
// FieldMap's true landmark positions. Every random draw comes from a seeded std::mt19937.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "touchline/angles.hpp"
#include "touchline/frame.hpp"
#include "touchline/robot/localisation/field_map.hpp"
#include "touchline/robot/localisation/pose_filter.hpp"

namespace touchline::robot::localisation::synthetic {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kFrameS = 1.0 / 30.0;  ///< a camera frame

inline double wrap(double a) { return a - 2 * kPiD * std::floor((a + kPiD) / (2 * kPiD)); }

/// `pose` moved by a robot-frame delta (exactly, as the world would).
inline Pose2D compose(const Pose2D& pose, const OdometryDelta& d) {
  const double c = std::cos(static_cast<double>(pose.theta_rad)), s = std::sin(static_cast<double>(pose.theta_rad));
  return {static_cast<float>(pose.x_mm + c * d.dx_mm - s * d.dy_mm),
          static_cast<float>(pose.y_mm + s * d.dx_mm + c * d.dy_mm),
          static_cast<float>(wrap(pose.theta_rad + d.dtheta_rad))};
}

/// The camera's noise in these tests: a little lower than the filter assumes.
struct CameraNoise {
  double range_sigma_mm = 20.0;
  double range_sigma_per_mm = 0.05;
  double bearing_sigma_rad = 0.03;
};

/// The camera: a 60-degree view around the head yaw, out to max_range_mm.
struct Camera {
  double half_view_rad = 30.0 * kPiD / 180.0;
  double max_range_mm = 4000.0;
  CameraNoise noise;
};

/// An observation of the point (x, y) from `truth`, with the camera's noise.
inline Observation observe(const Pose2D& truth, double x_mm, double y_mm, ObjectKind kind, int id,
                           const CameraNoise& noise, std::mt19937& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double dx = x_mm - truth.x_mm, dy = y_mm - truth.y_mm;
  const double range = std::hypot(dx, dy);
  Observation o;
  o.kind = kind;
  o.id = id;
  o.distance_mm = static_cast<float>(
      std::max(0.0, range + (noise.range_sigma_mm + noise.range_sigma_per_mm * range) * gauss(rng)));
  o.heading_rad =
      static_cast<float>(wrap(std::atan2(dy, dx) - truth.theta_rad + noise.bearing_sigma_rad * gauss(rng)));
  return o;
}

/// Whether the point is in the camera's view with the head at `head_yaw_rad`.
inline bool visible(const Camera& camera, const Pose2D& truth, double head_yaw_rad, double x_mm, double y_mm) {
  const double dx = x_mm - truth.x_mm, dy = y_mm - truth.y_mm;
  if (std::hypot(dx, dy) >= camera.max_range_mm) return false;
  return std::fabs(wrap(std::atan2(dy, dx) - truth.theta_rad - head_yaw_rad)) < camera.half_view_rad;
}

/// Every landmark the camera sees from `truth`, with noise.
inline std::vector<Observation> see_landmarks(const FieldMap& map, const Camera& camera, const Pose2D& truth,
                                              double head_yaw_rad, std::mt19937& rng) {
  std::vector<Observation> seen;
  for (const Landmark& l : map.landmarks())
    if (visible(camera, truth, head_yaw_rad, l.at.x_mm, l.at.y_mm))
      seen.push_back(observe(truth, l.at.x_mm, l.at.y_mm, l.kind, l.id, camera.noise, rng));
  return seen;
}

/// The odometry a walk reports for a true robot-frame motion: translation scaled by
/// `translation_scale`, turns by `turn_scale`, a steady heading drift, and white noise.
struct OdometryError {
  double translation_scale = 1.0;
  double turn_scale = 1.0;
  double drift_rad_per_s = 0.0;
  double xy_sigma_mm = 0.0;      ///< per frame
  double theta_sigma_rad = 0.0;  ///< per frame

  OdometryDelta report(const OdometryDelta& truth, double dt_s, std::mt19937& rng) const {
    std::normal_distribution<double> gauss(0.0, 1.0);
    return {truth.dx_mm * translation_scale + xy_sigma_mm * gauss(rng),
            truth.dy_mm * translation_scale + xy_sigma_mm * gauss(rng),
            truth.dtheta_rad * turn_scale + drift_rad_per_s * dt_s + theta_sigma_rad * gauss(rng)};
  }
};

/// Walks through waypoints in turn: turns towards the next one and walks forward when
/// roughly facing it, like the `goto` behaviour.
class WaypointWalker {
 public:
  explicit WaypointWalker(std::vector<FieldPoint> waypoints) : waypoints_(std::move(waypoints)) {}

  /// The true robot-frame motion for one frame of `dt_s` seconds from `truth`.
  OdometryDelta step(const Pose2D& truth, double dt_s) {
    const FieldPoint& target = waypoints_[next_];
    const double dx = target.x_mm - truth.x_mm, dy = target.y_mm - truth.y_mm;
    if (std::hypot(dx, dy) < 200.0) next_ = (next_ + 1) % waypoints_.size();
    const double error = wrap(std::atan2(dy, dx) - truth.theta_rad);
    const double turn = std::clamp(1.5 * error, -kMaxTurnRadS, kMaxTurnRadS);
    const double forward = kForwardMmS * std::max(0.0, std::cos(error));
    return {forward * dt_s, 0.0, turn * dt_s};
  }

 private:
  static constexpr double kForwardMmS = 200.0;
  static constexpr double kMaxTurnRadS = 0.8;
  std::vector<FieldPoint> waypoints_;
  size_t next_ = 0;
};

/// Head sweep: +-1 rad over a 3 s period, as a scanning behaviour looks around.
inline double head_yaw(double t_s) { return 1.0 * std::sin(2 * kPiD * t_s / 3.0); }

} // namespace touchline::robot::localisation::synthetic
