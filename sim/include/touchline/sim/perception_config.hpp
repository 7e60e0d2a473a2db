#pragma once
// What the perception pipeline (perception.hpp) is told by a world config: the camera
// ([camera]), the camera's noise and faults ([noise]) and the sonar ([sonar]). Every
// default is documented with its unit; config/spl2011.ini lists the same values.
#include "touchline/ini.hpp"
#include "touchline/sim/camera.hpp"
#include "touchline/sim/sonar.hpp"
#include "touchline/sim/touch.hpp"

namespace touchline::sim {

/// Measurement noise and detection faults of the camera. All Gaussian noise is zero-mean.
struct NoiseDef {
  /// Distance noise sigma = distance_sd_mm + distance_sd_fraction * distance: a fixed part
  /// (pixel quantisation) plus a part proportional to the distance (a pixel spans more
  /// ground far away).
  float distance_sd_mm = 10.f;         ///< mm
  float distance_sd_fraction = 0.05f;  ///< dimensionless (0.05: 5 % of the distance)
  /// Bearing noise sigma = bearing_sd_rad + bearing_sd_rad_per_m * distance in metres:
  /// far objects are few pixels wide, so their centre is less certain.
  float bearing_sd_rad = 0.02f;        ///< rad (about 1.1 degrees)
  float bearing_sd_rad_per_m = 0.01f;  ///< rad per metre of distance
  /// Probability that an object in view (and not occluded) is not reported this frame.
  float ball_miss_probability = 0.05f;     ///< per ball per frame, 0..1
  float landmark_miss_probability = 0.1f;  ///< per post / corner / line end / mark per frame, 0..1
  float robot_miss_probability = 0.2f;     ///< per other robot per frame, 0..1
  /// Probability per frame of a phantom ball when the real ball is not reported (the
  /// vision reports at most one ball a frame): somewhere in the field of view, at a
  /// distance uniform in (0, min(phantom_ball_max_distance_mm, camera range)].
  float phantom_ball_probability = 0.f;        ///< per frame, 0..1
  float phantom_ball_max_distance_mm = 2000.f; ///< mm
};

struct PerceptionDef {
  CameraDef camera;                 ///< [camera]: thesis 2.2.5's 60-degree view and pitch-dependent range
  /// [camera] Other robots hide the ball, posts and field features behind them: a robot's
  /// body is a disc of this radius about its body centre. 0: nothing is occluded.
  float occluder_radius_mm = 120.f; ///< mm
  NoiseDef noise;                   ///< [noise]
  SonarDef sonar;                   ///< [sonar]: thesis Algorithm 2.4's 1 m x +-100 mm corridor
  /// [sonar] Gaussian noise on a reading that sees something (a reading of 1, nothing
  /// seen, stays 1). 0: the thesis's exact readings.
  float sonar_noise_sd_mm = 0.f;    ///< mm
  /// [sonar] Whether the goal posts echo as well as other robots' bodies.
  bool sonar_sees_goal_posts = true;
  TouchDef touch;                   ///< [touch]: foot bumpers and arm contact
  /// [inertial] Gaussian noise on the gyro's yaw change over one frame: a random walk of
  /// the integrated heading, 0.002 rad a frame is 0.011 rad after a second and 0.09 rad
  /// after a minute. 0: the body's exact turn.
  float gyro_turn_sd_rad = 0.002f;  ///< rad per frame
};

/// Binds [camera], [noise], [sonar], [touch] and [inertial] keys (e.g. "noise.ball_miss_probability").
void bind(IniSchema& schema, PerceptionDef& def);

/// Checks ranges (probabilities in [0, 1], non-negative noise, a field of view in
/// (0, pi), min_pitch < max_pitch, positive ranges). Throws ConfigError naming the key,
/// e.g. "noise.ball_miss_probability must be in [0, 1] (got 1.5)".
void validate(const PerceptionDef& def);

} // namespace touchline::sim
