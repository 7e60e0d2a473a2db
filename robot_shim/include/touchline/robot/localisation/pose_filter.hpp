#pragma once
// An extended Kalman filter over the robot's field pose (x, y, theta): predicted with the
// walk's odometry, corrected with range/bearing observations of landmarks whose ids the
// camera reports (so the symmetric field is no ambiguity). Each correction is iterated
// (re-linearised at the corrected pose), which keeps a near landmark seen from a poor
// guess from making the filter confident in a wrong pose. Outliers are gated. Plain
// arrays in the interface; the matrix algebra (Eigen) stays in the .cpp.
#include <array>
#include <cstdint>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/robot/localisation/field_map.hpp"

namespace touchline::robot::localisation {

/// Noise models and thresholds of the pose filter.
struct PoseFilterDef {
  // Odometry (process) noise. Variances grow with the motion itself, per millimetre or
  // radian rather than per call, so the result does not depend on how often predict runs.
  double odo_xy_var_per_mm = 5.0;      ///< mm^2 of variance along each robot-frame axis per mm walked (sigma ~70 mm after 1 m)
  double odo_theta_var_per_rad = 0.01; ///< rad^2 per rad turned (sigma ~0.1 rad after 1 rad)
  double odo_theta_var_per_mm = 1e-5;  ///< rad^2 per mm walked: slipping feet turn the body (sigma ~0.1 rad after 1 m)
  double odo_xy_var_per_call = 0.25;   ///< mm^2 per predict even standing still (pushes, sway)
  double odo_theta_var_per_call = 1e-6;///< rad^2 per predict even standing still
  // The heading's noise when the gyro measured the turn (OdometryDelta::turn_from_gyro): the
  // gyro feels what the feet's slipping and contacts do to the body, so only its own noise
  // and the torso's sway are left. Modelling the walk's much larger heading noise instead
  // lets a landmark's bearing error, which a position dragged off by a blocked walk
  // explains, re-aim a right heading (0.4 rad in one match of 80, then 30 s lost).
  double gyro_theta_var_per_call = 4e-6;  ///< rad^2 per predict (sigma 0.002 rad a camera frame, the world's inertial.gyro_turn_sd_rad)
  double gyro_theta_var_per_rad = 1e-4;   ///< rad^2 per rad turned (sigma 1 % scale error)
  double gyro_theta_var_per_mm = 3e-6;    ///< rad^2 per mm walked: the torso the gyro sits in yaws against the feet in each step (sigma ~0.05 rad after 1 m)

  // Landmark (measurement) noise: range error grows with distance, as a camera's does.
  double range_sigma_mm = 50.0;        ///< mm, range sigma at zero distance
  double range_sigma_per_mm = 0.1;     ///< range sigma per mm of distance (10 %)
  double bearing_sigma_rad = 0.05;     ///< rad, bearing sigma at zero distance
  double bearing_sigma_per_mm = 1e-5;  ///< rad per mm of distance (0.01 rad per metre)
  double min_range_mm = 100.0;         ///< closer observations are ignored (bearing is meaningless at the body centre)
  int update_iterations = 5;           ///< iterated-EKF re-linearisations per observation at most (1: plain EKF)

  // Outliers.
  double gate_mahalanobis_sq = 13.8;   ///< squared Mahalanobis distance beyond which an observation is rejected (chi^2, 2 dof, 99.9 %)
  int max_rejections_in_a_row = 10;    ///< this many rejections with no acceptance between: the pose itself must be wrong (pushed, picked up), so ...
  double lost_sigma_xy_mm = 500.0;     ///< ... add this much position sigma (mm) ...
  double lost_sigma_theta_rad = 0.5;   ///< ... and heading sigma (rad) to the covariance.

  // A heading jump (a contact turned the robot, unseen by odometry): rejected landmarks whose
  // range fits the estimate (so the position is not what is wrong) but whose bearing does
  // not each vote for the heading error their bearing implies; enough votes that agree
  // re-aim the heading on the landmarks at once (widening the covariance alone lets the
  // landmarks drag the position instead, before the heading follows).
  double heading_jump_range_gate_sq = 6.63; ///< the range's own squared innovation over its variance must be within this (chi^2, 1 dof, 99 %)
  double heading_jump_min_range_mm = 300.0; ///< nearer landmarks do not vote (their bearing moves with the position)
  int heading_jump_votes = 3;               ///< votes within heading_jump_agree_rad of their median that re-aim the heading ...
  int heading_jump_landmarks = 2;           ///< ... from at least this many landmarks (one wrong id seen again and again agrees with itself)
  double heading_jump_agree_rad = 0.2;      ///< rad
  int heading_jump_window = 30;             ///< predicts (camera frames, 1 s) a vote counts for
  double heading_jump_sigma_theta_rad = 0.2;///< heading sigma once re-aimed, rad
  double heading_jump_sigma_xy_mm = 150.0;  ///< position sigma added once re-aimed (the wrong heading dragged it), mm

  // A pose known from the rules (the robot's start on its touchline, a penalty's return).
  double initial_sigma_xy_mm = 300.0;  ///< mm: how far the robot may stand from where the rules place it
  double initial_sigma_theta_rad = 0.3;///< rad
};

/// Row-major 3x3 covariance of (x mm, y mm, theta rad).
using PoseCovariance = std::array<double, 9>;

/// A covariance with independent x, y, theta.
PoseCovariance diagonal_covariance(double sigma_x_mm, double sigma_y_mm, double sigma_theta_rad);

/// Motion in the robot frame of its start (+x forward, +y left) since the last predict.
struct OdometryDelta {
  double dx_mm = 0;
  double dy_mm = 0;
  double dtheta_rad = 0;
  bool turn_from_gyro = false;  ///< dtheta_rad is the gyro's: the heading noise is the gyro's, not the walk's
};

/// The robot-frame motion from odometry pose `before` to odometry pose `after` (both in
/// the walk's odometry frame, e.g. MotionBlackboard::odometry at two frames).
OdometryDelta odometry_delta(const Pose2D& before, const Pose2D& after);

enum class UpdateResult : int8_t {
  kAccepted,  ///< the observation corrected the estimate
  kRejected,  ///< its innovation failed the gate: an outlier (or the estimate is off)
  kIgnored,   ///< not a known landmark, or too close to use
};

struct PoseFilterStats {
  int64_t accepted = 0;
  int64_t rejected = 0;
  int64_t ignored = 0;
  int64_t inflations = 0;  ///< times max_rejections_in_a_row widened the covariance
  int64_t heading_jumps = 0; ///< times the landmarks re-aimed the heading
  double last_mahalanobis_sq = 0; ///< of the last gated observation
};

class PoseFilter {
 public:
  /// Starts at `initial` with the def's initial sigmas (a pose known from the rules).
  explicit PoseFilter(FieldMap field = {}, PoseFilterDef def = {}, const Pose2D& initial = {});

  /// Re-initialises at `pose` with `covariance`.
  void reset(const Pose2D& pose, const PoseCovariance& covariance);
  /// Re-initialises at `pose` with the def's initial sigmas.
  void reset(const Pose2D& pose);

  /// Moves the estimate by the odometry's motion and grows the covariance with it.
  void predict(const OdometryDelta& delta);
  /// Corrects the estimate with one observation (robot frame). Ball and robot
  /// observations are ignored.
  UpdateResult update(const Observation& observation);

  /// The estimate, theta in [-pi, pi).
  Pose2D pose() const;
  const PoseCovariance& covariance() const { return covariance_; }
  double sigma_x_mm() const;
  double sigma_y_mm() const;
  double sigma_theta_rad() const;

  const PoseFilterStats& stats() const { return stats_; }
  const FieldMap& field() const { return field_; }
  const PoseFilterDef& def() const { return def_; }

 private:
  FieldMap field_;
  PoseFilterDef def_;
  std::array<double, 3> mean_{};  ///< x mm, y mm, theta rad (wrapped)
  PoseCovariance covariance_{};
  PoseFilterStats stats_;
  int rejections_in_a_row_ = 0;
  /// Heading errors the recent rejected landmarks voted for, rad, and their age in predicts.
  struct HeadingVote {
    double error_rad;
    int age;
    int landmark; ///< which landmark voted (kind * 256 + id)
  };
  std::vector<HeadingVote> heading_votes_;

  /// A rejected observation whose range fits: its vote; re-aims the heading when enough agree.
  /// True when it re-aimed.
  bool vote_heading_jump(double range_innovation_sq_over_var, double bearing_innovation_rad,
                         double bearing_var, double range_mm, int landmark);
};

} // namespace touchline::robot::localisation
