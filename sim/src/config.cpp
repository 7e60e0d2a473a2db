#include "touchline/sim/config.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "touchline/angles.hpp"

namespace touchline::sim {

void bind(IniSchema& s, FieldDef& d) {
  s.bind("field.length_mm", &d.length_mm, "between the goal lines, mm")
      .bind("field.width_mm", &d.width_mm, "between the touchlines, mm")
      .bind("field.border_mm", &d.border_mm, "carpet beyond the lines to the walls, mm")
      .bind("field.line_width_mm", &d.line_width_mm, "painted line width, mm")
      .bind("field.goal_width_mm", &d.goal_width_mm, "between the goal posts' centres, mm")
      .bind("field.goal_depth_mm", &d.goal_depth_mm, "goal line to the back of the net, mm")
      .bind("field.goal_post_diameter_mm", &d.goal_post_diameter_mm, "goal post diameter, mm")
      .bind("field.goal_box_length_mm", &d.goal_box_length_mm, "goal box depth from the goal line, mm")
      .bind("field.goal_box_width_mm", &d.goal_box_width_mm, "goal box extent along the goal line, mm")
      .bind("field.penalty_area_length_mm", &d.penalty_area_length_mm, "penalty area depth, mm (0: none)")
      .bind("field.penalty_area_width_mm", &d.penalty_area_width_mm, "penalty area extent, mm (0: none)")
      .bind("field.penalty_mark_distance_mm", &d.penalty_mark_distance_mm, "penalty mark from the goal line, mm")
      .bind("field.centre_circle_diameter_mm", &d.centre_circle_diameter_mm, "centre circle diameter, mm");
}

void bind(IniSchema& s, PhysicsDef& d) {
  s.bind("physics.ball_diameter_mm", &d.ball_diameter_mm, "ball diameter, mm")
      .bind("physics.ball_mass_kg", &d.ball_mass_kg, "ball mass, kg")
      .bind("physics.ball_restitution", &d.ball_restitution, "ball bounce off feet, 0..1")
      .bind("physics.ball_rolling_decel_mm_s2", &d.ball_rolling_decel_mm_s2, "rolling resistance, mm/s^2")
      .bind("physics.ball_linear_damping", &d.ball_linear_damping, "velocity-proportional drag, 1/s")
      .bind("physics.foot_length_mm", &d.foot_length_mm, "foot length (robot x), mm")
      .bind("physics.foot_width_mm", &d.foot_width_mm, "foot width (robot y), mm")
      .bind("physics.foot_mass_kg", &d.foot_mass_kg, "mass of one foot, kg")
      .bind("physics.foot_friction", &d.foot_friction, "friction of every contact")
      .bind("physics.wall_restitution", &d.wall_restitution, "ball bounce off the walls, 0..1")
      .bind("physics.post_restitution", &d.post_restitution, "ball bounce off the posts, 0..1")
      .bind("physics.net_restitution", &d.net_restitution, "ball bounce off the nets, 0..1")
      .bind("physics.substeps", &d.substeps, "Box2D steps per 10 ms motion tick")
      .bind("physics.velocity_iterations", &d.velocity_iterations, "Box2D velocity iterations")
      .bind("physics.position_iterations", &d.position_iterations, "Box2D position iterations");
}

void bind(IniSchema& s, MatchDef& d) {
  s.bind("match.team_size", &d.team_size, "robots per team, 1..7")
      .bind("match.duration_s", &d.duration_s, "simulated match length, s")
      .bind("match.foot_separation_mm", &d.foot_separation_mm, "feet apart when placed, mm")
      .bind("match.ball_start_x_mm", &d.ball_start_x_mm, "ball position at kick-off, x, mm")
      .bind("match.ball_start_y_mm", &d.ball_start_y_mm, "ball position at kick-off, y, mm");
}

namespace {

template <typename T>
std::string str(T value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void require_below(const char* key, float value, const std::string& limit_name, float limit) {
  if (!(value < limit)) config_fail(key, ("< " + limit_name + " = " + str(limit)).c_str(), value);
}
void require_at_most(const char* key, float value, const std::string& limit_name, float limit) {
  if (!(value <= limit)) config_fail(key, ("<= " + limit_name + " = " + str(limit)).c_str(), value);
}

void validate_field(const FieldDef& f) {
  require_positive("field.length_mm", f.length_mm);
  require_positive("field.width_mm", f.width_mm);
  require_positive("field.border_mm", f.border_mm);
  require_positive("field.line_width_mm", f.line_width_mm);
  require_positive("field.goal_width_mm", f.goal_width_mm);
  require_positive("field.goal_depth_mm", f.goal_depth_mm);
  require_positive("field.goal_post_diameter_mm", f.goal_post_diameter_mm);
  require_positive("field.goal_box_length_mm", f.goal_box_length_mm);
  require_positive("field.goal_box_width_mm", f.goal_box_width_mm);
  require_non_negative("field.penalty_area_length_mm", f.penalty_area_length_mm);
  require_non_negative("field.penalty_area_width_mm", f.penalty_area_width_mm);
  require_positive("field.penalty_mark_distance_mm", f.penalty_mark_distance_mm);
  require_positive("field.centre_circle_diameter_mm", f.centre_circle_diameter_mm);

  const float half_length = f.length_mm / 2;
  if (!(f.goal_width_mm + f.goal_post_diameter_mm < f.width_mm))
    config_fail("field.goal_width_mm",  // the posts stand on the goal line, inside the touchlines
         ("< field.width_mm - goal_post_diameter_mm = " + str(f.width_mm - f.goal_post_diameter_mm))
             .c_str(),
         f.goal_width_mm);
  require_below("field.goal_depth_mm", f.goal_depth_mm, "field.border_mm", f.border_mm);
  require_below("field.goal_box_length_mm", f.goal_box_length_mm, "half field.length_mm", half_length);
  require_at_most("field.goal_box_width_mm", f.goal_box_width_mm, "field.width_mm", f.width_mm);
  require_below("field.penalty_area_length_mm", f.penalty_area_length_mm, "half field.length_mm",
                half_length);
  require_at_most("field.penalty_area_width_mm", f.penalty_area_width_mm, "field.width_mm", f.width_mm);
  require_below("field.penalty_mark_distance_mm", f.penalty_mark_distance_mm, "half field.length_mm",
                half_length);
  require_below("field.centre_circle_diameter_mm", f.centre_circle_diameter_mm, "field.width_mm",
                f.width_mm);
}

void validate_physics(const PhysicsDef& p) {
  require_positive("physics.ball_diameter_mm", p.ball_diameter_mm);
  require_positive("physics.ball_mass_kg", p.ball_mass_kg);
  require_fraction("physics.ball_restitution", p.ball_restitution);
  require_non_negative("physics.ball_rolling_decel_mm_s2", p.ball_rolling_decel_mm_s2);
  require_non_negative("physics.ball_linear_damping", p.ball_linear_damping);
  require_positive("physics.foot_length_mm", p.foot_length_mm);
  require_positive("physics.foot_width_mm", p.foot_width_mm);
  require_positive("physics.foot_mass_kg", p.foot_mass_kg);
  require_non_negative("physics.foot_friction", p.foot_friction);
  require_fraction("physics.wall_restitution", p.wall_restitution);
  require_fraction("physics.post_restitution", p.post_restitution);
  require_fraction("physics.net_restitution", p.net_restitution);
  if (p.substeps < 1) config_fail("physics.substeps", ">= 1", p.substeps);
  if (p.velocity_iterations < 1) config_fail("physics.velocity_iterations", ">= 1", p.velocity_iterations);
  if (p.position_iterations < 1) config_fail("physics.position_iterations", ">= 1", p.position_iterations);
}

void validate_match(const MatchDef& m) {
  if (m.team_size < 1 || m.team_size > kMaxTeamSize)
    config_fail("match.team_size", ("1.." + std::to_string(kMaxTeamSize)).c_str(), m.team_size);
  require_positive("match.duration_s", m.duration_s);
  require_positive("match.foot_separation_mm", m.foot_separation_mm);
}

} // namespace

void validate(const WorldConfig& config) {
  validate_field(config.field);
  validate_physics(config.physics);
  validate_match(config.match);
  validate(config.perception);
  validate(config.rules);
  validate(config.comm);
  const Field field(config.field);
  if (!field.on_carpet(config.match.ball_start_x_mm, config.match.ball_start_y_mm))
    throw ConfigError("match.ball_start_x_mm/_y_mm must be on the carpet (got " +
                      str(config.match.ball_start_x_mm) + ", " + str(config.match.ball_start_y_mm) + ")");
}

void bind(IniSchema& schema, WorldConfig& config) {
  bind(schema, config.field);
  bind(schema, config.physics);
  bind(schema, config.match);
  bind(schema, config.perception);
  bind(schema, config.rules);
  bind(schema, config.comm);
}

WorldConfig load_world_config(const std::string& path, const std::vector<std::string>& overrides) {
  WorldConfig config;
  IniSchema schema("world config");
  bind(schema, config);
  if (!path.empty()) schema.read_file(path);
  for (const std::string& assignment : overrides) schema.apply_override(assignment);
  validate(config);
  return config;
}

Pose2D initial_pose(const Field& field, int team_size, RobotId id) {
  // Team 0's half is x < 0; its robots stand on the touchline y = -half_width, facing
  // +y into the field, spread evenly between the goal box and the centre circle, player
  // 1 (the keeper) nearest its own goal. Team 1 is the same picture turned by 180
  // degrees about the centre spot (its half x > 0, touchline y = +half_width, facing
  // -y), so each team sees the same start from its own side.
  const FieldDef& f = field.def();
  const float near_goal = field.half_length() - f.goal_box_length_mm;
  const float near_centre = f.centre_circle_diameter_mm / 2;
  const int n = std::max(1, team_size);
  const float slot = (near_goal - near_centre) / static_cast<float>(n);
  const float distance_from_centre = near_goal - (static_cast<float>(id.player) - 0.5f) * slot;
  const Pose2D team0{-distance_from_centre, -field.half_width(), kPi / 2};
  if (id.team == 0) return team0;
  return Pose2D{-team0.x_mm, -team0.y_mm, -kPi / 2};
}

} // namespace touchline::sim
