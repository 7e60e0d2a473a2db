#pragma once
// A constant-velocity Kalman filter for the ball in the field frame, fed with the
// camera's ball observations placed on the field with the robot's pose estimate. Between
// sightings the ball rolls on and slows down as the world's ball does (constant rolling
// deceleration plus linear damping), so a lost ball comes to rest where it was heading.
//
// The track is the ball as this robot sees it, placed with its pose estimate: an error
// of that estimate is shared by every sighting (it changes slowly, with odometry and
// landmarks), so it is not a sighting's own noise, and when a landmark corrects the pose
// the ball moves with the robot (move_with); B-Human's ball model, relative to the robot,
// works so too. Counting the pose's uncertainty as each sighting's noise made the track
// trust the camera too little, and a rolling ball near the robot lagged its sightings (16
// C++ matches, cpp:Team v cpp:Striker, seeds 17-32: relative to a robot within 400 mm of
// it, a rolling ball was a median 67 mm off the truth, 133 mm at the 90th percentile; 29
// and 83 mm now). The pose's uncertainty is added where the ball is reported on the field
// (field_position_covariance).
#include <array>
#include <cstdint>

#include "touchline/frame.hpp"
#include "touchline/robot/localisation/field_map.hpp"
#include "touchline/robot/localisation/pose_filter.hpp"
#include "touchline/robot_api/geometry.hpp"

namespace touchline::robot::localisation {

struct BallFilterDef {
  // Motion model: the world's defaults ([physics] in config/spl2011.ini).
  double rolling_decel_mm_s2 = 300.0;  ///< mm/s^2, constant rolling resistance
  double linear_damping_per_s = 0.2;   ///< 1/s, velocity-proportional drag
  double accel_sigma_mm_s2 = 500.0;    ///< mm/s^2, white-noise acceleration: touches, bounces, model error

  // Observation noise, as the pose filter's landmarks.
  double range_sigma_mm = 30.0;        ///< mm, range sigma at zero distance
  double range_sigma_per_mm = 0.08;    ///< range sigma per mm of distance (8 %)
  double bearing_sigma_rad = 0.04;     ///< rad

  double initial_speed_sigma_mm_s = 1500.0; ///< mm/s, velocity sigma of a freshly (re)initialised ball
  /// Squared Mahalanobis distance beyond which a sighting cannot be the ball we track (it
  /// was kicked, or we were wrong): the filter re-initialises there (chi^2, 2 dof, 99.9 %).
  double gate_mahalanobis_sq = 13.8;
};

struct BallFilterStats {
  int64_t updates = 0;            ///< sightings used
  int64_t reinitialisations = 0;  ///< sightings that failed the gate and restarted the track
};

class BallFilter {
 public:
  explicit BallFilter(BallFilterDef def = {});

  /// Rolls the ball on by `dt_s` seconds: call once per camera frame. Counts the frame
  /// as lost until update() sees the ball.
  void predict(double dt_s);
  /// Folds in a ball sighting (robot frame) seen from `robot`, the pose estimate the
  /// track is placed with. Returns false for anything but a ball.
  bool update(const Observation& ball, const Pose2D& robot);
  /// The robot's pose estimate was corrected from `from` to `to` (a landmark): the ball,
  /// seen from that estimate, keeps its place relative to the robot (position, velocity
  /// and covariance move rigidly with it). Nothing moves before the first sighting.
  void move_with(const Pose2D& from, const Pose2D& to);

  /// Whether the ball has ever been seen.
  bool seen() const { return seen_; }
  /// Frames (predicts) since the ball was last seen.
  int lost_count() const { return lost_count_; }
  FieldPoint position() const { return {state_[0], state_[1]}; }
  FieldPoint velocity() const { return {state_[2], state_[3]}; } ///< mm/s
  /// The ball seen from `robot`.
  api::RRCoord relative_to(const Pose2D& robot) const;
  /// Row-major 4x4 covariance of (x mm, y mm, vx mm/s, vy mm/s).
  const std::array<double, 16>& covariance() const { return covariance_; }
  /// Square root of the larger position variance, mm.
  double position_sigma_mm() const;
  /// Row-major 2x2 covariance of the ball's field position, mm^2: the track's own plus
  /// what the uncertainty `robot_covariance` of the pose `robot` it is seen from adds.
  std::array<double, 4> field_position_covariance(const Pose2D& robot, const PoseCovariance& robot_covariance) const;

  const BallFilterStats& stats() const { return stats_; }

 private:
  BallFilterDef def_;
  std::array<double, 4> state_{};  ///< x, y mm; vx, vy mm/s (field frame)
  std::array<double, 16> covariance_{};
  BallFilterStats stats_;
  bool seen_ = false;
  int lost_count_ = 0;
};

} // namespace touchline::robot::localisation
