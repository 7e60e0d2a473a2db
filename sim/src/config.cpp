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
      .bind("physics.max_foot_spread_mm", &d.max_foot_spread_mm, "a robot's foot centres at most this far apart, mm")
      .bind("physics.max_foot_twist_rad", &d.max_foot_twist_rad,
            "one foot's heading at most this far from the other's, rad (0: no limit)")
      .bind("physics.stance_return_mm_s", &d.stance_return_mm_s,
            "a lifted foot's speed back to the walk's stance, mm/s (0: never)")
      .bind("physics.stance_return_rad_s", &d.stance_return_rad_s,
            "a lifted foot's turn back to the walk's stance, rad/s (0: never)")
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

// Bounds for what Box2D is given. Its manual (2.4, "Units") asks for moving shapes of 0.1
// to 10 m and static ones of at most 50 m; far outside, its float arithmetic breaks down.
// Measured with Debian's Box2D 2.4: a 0.1 mm foot aborts it (b2PolygonShape::ComputeMass
// asserts an area above FLT_EPSILON m^2), a 3e38 kg or infinite ball mass makes every
// position NaN at the first step. The bounds below are generous (several times any
// RoboCup field, robot or ball), and a test drives a world with every one at its extreme
// (Config.ExtremeValuesWithinTheBoundsKeepTheWorldSane).

/// The field's length and width are at most kMaxFieldSide_mm (frame.hpp); with the
/// border, the longest wall (length + 2 border + 1 m of wall) stays under 50 m.
constexpr float kMaxBorder_mm = 5000.f;
/// Lines are painted: wider than a metre is a typo.
constexpr float kMaxLineWidth_mm = 1000.f;

void validate_field(const FieldDef& f) {
  require_positive("field.length_mm", f.length_mm, kMaxFieldSide_mm);
  require_positive("field.width_mm", f.width_mm, kMaxFieldSide_mm);
  require_positive("field.border_mm", f.border_mm, kMaxBorder_mm);
  require_positive("field.line_width_mm", f.line_width_mm, kMaxLineWidth_mm);
  // The rest are bounded above by the field itself (below): the goal inside the width,
  // the net inside the border, the boxes, marks and circle inside the field.
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

/// Ball and feet: from a marble to a beach ball, feet from 1 cm to 1 m.
constexpr float kMinBody_mm = 10.f, kMaxBody_mm = 1000.f;
/// Masses from 1 g (a table-tennis ball is 2.7 g) to a heavy robot; the ratio of the two
/// stays within 1e5 (the extreme the test drives).
constexpr float kMinBallMass_kg = 0.001f, kMaxBallMass_kg = 10.f;
constexpr float kMinFootMass_kg = 0.01f, kMaxFootMass_kg = 100.f;
/// Rolling resistance up to 10 g (a 10 m/s shot stops within 0.1 s), drag up to 100/s.
constexpr float kMaxRollingDecel_mm_s2 = 100000.f, kMaxLinearDamping_1_s = 100.f;
/// Coulomb friction: rubber on concrete is about 1.
constexpr float kMaxFriction = 10.f;
/// Box2D steps and solver iterations: 100 of either is 10-50 times the usual cost per tick;
/// more would make a match crawl without changing it.
constexpr int kMaxSubsteps = 100, kMaxIterations = 100;
/// A lifted foot's return to the stance: up to a kick's swing speed and a full turn in 0.1 s.
constexpr float kMaxStanceReturn_mm_s = 3000.f, kMaxStanceReturn_rad_s = 60.f;

void validate_physics(const PhysicsDef& p) {
  require_range("physics.ball_diameter_mm", p.ball_diameter_mm, kMinBody_mm, kMaxBody_mm);
  require_range("physics.ball_mass_kg", p.ball_mass_kg, kMinBallMass_kg, kMaxBallMass_kg);
  require_fraction("physics.ball_restitution", p.ball_restitution);
  require_non_negative("physics.ball_rolling_decel_mm_s2", p.ball_rolling_decel_mm_s2, kMaxRollingDecel_mm_s2);
  require_non_negative("physics.ball_linear_damping", p.ball_linear_damping, kMaxLinearDamping_1_s);
  require_range("physics.foot_length_mm", p.foot_length_mm, kMinBody_mm, kMaxBody_mm);
  require_range("physics.foot_width_mm", p.foot_width_mm, kMinBody_mm, kMaxBody_mm);
  require_range("physics.foot_mass_kg", p.foot_mass_kg, kMinFootMass_kg, kMaxFootMass_kg);
  require_non_negative("physics.foot_friction", p.foot_friction, kMaxFriction);
  require_range("physics.max_foot_spread_mm", p.max_foot_spread_mm, kMinBody_mm, kMaxBody_mm);
  require_range("physics.max_foot_twist_rad", p.max_foot_twist_rad, 0.f, 3.f);
  require_range("physics.stance_return_mm_s", p.stance_return_mm_s, 0.f, kMaxStanceReturn_mm_s);
  require_range("physics.stance_return_rad_s", p.stance_return_rad_s, 0.f, kMaxStanceReturn_rad_s);
  require_fraction("physics.wall_restitution", p.wall_restitution);
  require_fraction("physics.post_restitution", p.post_restitution);
  require_fraction("physics.net_restitution", p.net_restitution);
  require_count("physics.substeps", p.substeps, 1, kMaxSubsteps);
  require_count("physics.velocity_iterations", p.velocity_iterations, 1, kMaxIterations);
  require_count("physics.position_iterations", p.position_iterations, 1, kMaxIterations);
}

constexpr float kMaxDuration_s = 1e9f;

void validate_match(const MatchDef& m) {
  require_count("match.team_size", m.team_size, 1, kMaxTeamSize);
  // Long enough for learning's endless episodes (SingleRobotSim asks for 1e9 s); the clock
  // counts whole microseconds in an int64_t, exact far beyond it.
  require_positive("match.duration_s", m.duration_s, kMaxDuration_s);
  require_positive("match.foot_separation_mm", m.foot_separation_mm, kMaxBody_mm);
}

} // namespace

void validate(const WorldConfig& config) {
  validate_field(config.field);
  validate_physics(config.physics);
  validate_match(config.match);
  validate(config.perception);
  validate(config.rules);
  validate(config.comm);
  if (config.match.foot_separation_mm > config.physics.max_foot_spread_mm)
    throw ConfigError("match.foot_separation_mm must be <= physics.max_foot_spread_mm (got " +
                      str(config.match.foot_separation_mm) + " > " + str(config.physics.max_foot_spread_mm) + ")");
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
