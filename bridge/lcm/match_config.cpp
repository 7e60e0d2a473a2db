#include "touchline/lcm/match_config.hpp"

#include <cstring>

namespace touchline::transport {

match_config_t to_lcm(const sim::WorldConfig& config, uint64_t seed, int64_t utime) {
  const sim::FieldDef& field = config.field;
  const sim::CameraDef& camera = config.perception.camera;
  match_config_t m;
  m.types_version = match_config_t::TYPES_VERSION;
  m.utime = utime;
  std::memcpy(&m.seed, &seed, sizeof seed); // LCM has no unsigned type: the same 64 bits
  m.team_size = static_cast<int8_t>(config.match.team_size);
  m.duration_s = config.match.duration_s;
  m.referee = config.rules.referee;
  m.half_s = config.rules.half_s;
  m.field_length_mm = field.length_mm;
  m.field_width_mm = field.width_mm;
  m.border_mm = field.border_mm;
  m.line_width_mm = field.line_width_mm;
  m.goal_width_mm = field.goal_width_mm;
  m.goal_depth_mm = field.goal_depth_mm;
  m.goal_post_diameter_mm = field.goal_post_diameter_mm;
  m.goal_box_length_mm = field.goal_box_length_mm;
  m.goal_box_width_mm = field.goal_box_width_mm;
  m.penalty_area_length_mm = field.penalty_area_length_mm;
  m.penalty_area_width_mm = field.penalty_area_width_mm;
  m.penalty_mark_distance_mm = field.penalty_mark_distance_mm;
  m.centre_circle_diameter_mm = field.centre_circle_diameter_mm;
  m.ball_diameter_mm = config.physics.ball_diameter_mm;
  m.foot_length_mm = config.physics.foot_length_mm;
  m.foot_width_mm = config.physics.foot_width_mm;
  m.foot_separation_mm = config.match.foot_separation_mm;
  m.camera_field_of_view_rad = camera.field_of_view_rad;
  m.camera_min_pitch_rad = camera.min_pitch_rad;
  m.camera_max_pitch_rad = camera.max_pitch_rad;
  m.camera_near_range_mm = camera.near_range_mm;
  m.camera_range_span_mm = camera.range_span_mm;
  m.sonar_range_mm = config.perception.sonar.range_mm;
  m.sonar_half_width_mm = config.perception.sonar.half_width_mm;
  return m;
}

} // namespace touchline::transport
