#pragma once
#include <vector>
// Shared set-up for the perception tests: a noiseless, faultless configuration to start
// from, and viewers on the SPL 2011 field (6000 x 4000; posts at x = +-3000, y = +-700).
#include "touchline/sim/perception.hpp"

namespace touchline::sim::testing {

/// No noise, no false negatives, no phantoms: observations are the bare geometry.
inline PerceptionDef exact() {
  PerceptionDef def;
  def.noise.distance_sd_mm = 0;
  def.noise.distance_sd_fraction = 0;
  def.noise.bearing_sd_rad = 0;
  def.noise.bearing_sd_rad_per_m = 0;
  def.noise.ball_miss_probability = 0;
  def.noise.landmark_miss_probability = 0;
  def.noise.robot_miss_probability = 0;
  def.noise.phantom_ball_probability = 0;
  def.sonar_noise_sd_mm = 0;
  def.gyro_turn_sd_rad = 0;
  return def;
}

constexpr float kHeadUp = -0.67f;  ///< pitch fully up: the camera sees 4000 mm
constexpr float kHeadDown = 0.51f; ///< pitch fully down: the camera sees 1000 mm

inline Viewer viewer(int team, int player, float x_mm, float y_mm, float theta_rad, float yaw_rad = 0,
                     float pitch_rad = kHeadUp) {
  return Viewer{RobotId{team, player}, Pose2D{x_mm, y_mm, theta_rad}, yaw_rad, pitch_rad};
}

inline BallTruth ball_at(float x_mm, float y_mm) {
  BallTruth b;
  b.x_mm = x_mm;
  b.y_mm = y_mm;
  return b;
}

/// The observation of `kind` (and landmark or player `id`) in `seen`, or nullptr.
inline const Observation* find(const std::vector<Observation>& seen, ObjectKind kind, int id = 0) {
  for (const Observation& o : seen)
    if (o.kind == kind && o.id == id) return &o;
  return nullptr;
}

} // namespace touchline::sim::testing
