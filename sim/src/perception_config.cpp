#include "touchline/sim/perception_config.hpp"

#include <sstream>
#include <string>

#include "touchline/angles.hpp"

namespace touchline::sim {

void bind(IniSchema& s, PerceptionDef& d) {
  s.bind("camera.field_of_view_rad", &d.camera.field_of_view_rad, "full horizontal view, rad")
      .bind("camera.min_pitch_rad", &d.camera.min_pitch_rad, "head pitch fully up (longest range), rad")
      .bind("camera.max_pitch_rad", &d.camera.max_pitch_rad, "head pitch fully down (shortest range), rad")
      .bind("camera.near_range_mm", &d.camera.near_range_mm, "visible range with the head fully down, mm")
      .bind("camera.range_span_mm", &d.camera.range_span_mm, "range gained from fully down to fully up, mm")
      .bind("camera.occluder_radius_mm", &d.occluder_radius_mm, "robot body disc that hides what is behind, mm")
      .bind("noise.distance_sd_mm", &d.noise.distance_sd_mm, "fixed part of the distance sigma, mm")
      .bind("noise.distance_sd_fraction", &d.noise.distance_sd_fraction, "distance sigma per mm of distance")
      .bind("noise.bearing_sd_rad", &d.noise.bearing_sd_rad, "fixed part of the bearing sigma, rad")
      .bind("noise.bearing_sd_rad_per_m", &d.noise.bearing_sd_rad_per_m, "bearing sigma per metre, rad/m")
      .bind("noise.ball_miss_probability", &d.noise.ball_miss_probability, "ball in view not reported, 0..1")
      .bind("noise.landmark_miss_probability", &d.noise.landmark_miss_probability,
            "landmark in view not reported, 0..1")
      .bind("noise.robot_miss_probability", &d.noise.robot_miss_probability, "robot in view not reported, 0..1")
      .bind("noise.phantom_ball_probability", &d.noise.phantom_ball_probability,
            "phantom ball per frame without a real one, 0..1")
      .bind("noise.phantom_ball_max_distance_mm", &d.noise.phantom_ball_max_distance_mm,
            "farthest phantom ball, mm")
      .bind("sonar.range_mm", &d.sonar.range_mm, "farthest obstacle reported, mm")
      .bind("sonar.half_width_mm", &d.sonar.half_width_mm, "corridor half width, mm")
      .bind("sonar.noise_sd_mm", &d.sonar_noise_sd_mm, "reading noise sigma, mm")
      .bind("sonar.sees_goal_posts", &d.sonar_sees_goal_posts, "goal posts echo too, true/false")
      .bind("touch.distance_mm", &d.touch.distance_mm, "another robot's centre this near touches, mm (0: none)")
      .bind("touch.post_distance_mm", &d.touch.post_distance_mm, "a goal post's centre this near touches, mm (0: none)")
      .bind("inertial.gyro_turn_sd_rad", &d.gyro_turn_sd_rad, "gyro noise on a frame's yaw change, rad");
}

void validate(const PerceptionDef& d) {
  if (!(d.camera.field_of_view_rad > 0 && d.camera.field_of_view_rad < kPi))
    config_fail("camera.field_of_view_rad", "in (0, pi)", d.camera.field_of_view_rad);
  require_range("camera.min_pitch_rad", d.camera.min_pitch_rad, -kPi, kPi);
  require_range("camera.max_pitch_rad", d.camera.max_pitch_rad, -kPi, kPi);
  if (!(d.camera.min_pitch_rad < d.camera.max_pitch_rad))
    config_fail("camera.min_pitch_rad", "< camera.max_pitch_rad = " + std::to_string(d.camera.max_pitch_rad),
         d.camera.min_pitch_rad);
  require_positive("camera.near_range_mm", d.camera.near_range_mm);
  require_non_negative("camera.range_span_mm", d.camera.range_span_mm);
  require_non_negative("camera.occluder_radius_mm", d.occluder_radius_mm);

  require_non_negative("noise.distance_sd_mm", d.noise.distance_sd_mm);
  require_non_negative("noise.distance_sd_fraction", d.noise.distance_sd_fraction);
  require_non_negative("noise.bearing_sd_rad", d.noise.bearing_sd_rad);
  require_non_negative("noise.bearing_sd_rad_per_m", d.noise.bearing_sd_rad_per_m);
  require_fraction("noise.ball_miss_probability", d.noise.ball_miss_probability);
  require_fraction("noise.landmark_miss_probability", d.noise.landmark_miss_probability);
  require_fraction("noise.robot_miss_probability", d.noise.robot_miss_probability);
  require_fraction("noise.phantom_ball_probability", d.noise.phantom_ball_probability);
  require_positive("noise.phantom_ball_max_distance_mm", d.noise.phantom_ball_max_distance_mm);

  require_positive("sonar.range_mm", d.sonar.range_mm);
  require_positive("sonar.half_width_mm", d.sonar.half_width_mm);
  require_non_negative("sonar.noise_sd_mm", d.sonar_noise_sd_mm);
  require_non_negative("touch.distance_mm", d.touch.distance_mm);
  require_non_negative("touch.post_distance_mm", d.touch.post_distance_mm);
  require_range("inertial.gyro_turn_sd_rad", d.gyro_turn_sd_rad, 0.f, 1.f);
}

} // namespace touchline::sim
