#include "touchline/python/runswift/field.hpp"

#include "touchline/frame.hpp"
#include "touchline/ini.hpp"

namespace touchline::python::runswift {

SplFieldDef load_spl_field(const std::string& path) {
  SplFieldDef f;
  if (path.empty()) return f;
  IniSchema schema("field");
  schema.bind("field.length_mm", &f.length_mm, "between the goal lines, mm")
      .bind("field.width_mm", &f.width_mm, "between the touchlines, mm")
      .bind("field.border_mm", &f.border_mm, "carpet beyond the lines, mm")
      .bind("field.line_width_mm", &f.line_width_mm, "line width, mm")
      .bind("field.goal_width_mm", &f.goal_width_mm, "between the posts' centres, mm")
      .bind("field.goal_post_diameter_mm", &f.goal_post_diameter_mm, "post diameter, mm")
      .bind("field.goal_box_length_mm", &f.goal_box_length_mm, "goal box depth, mm")
      .bind("field.goal_box_width_mm", &f.goal_box_width_mm, "goal box width, mm")
      .bind("field.penalty_area_length_mm", &f.penalty_area_length_mm, "penalty area depth, mm")
      .bind("field.penalty_area_width_mm", &f.penalty_area_width_mm, "penalty area width, mm")
      .bind("field.penalty_mark_distance_mm", &f.penalty_mark_distance_mm, "penalty mark from the goal line, mm")
      .bind("field.centre_circle_diameter_mm", &f.centre_circle_diameter_mm, "centre circle diameter, mm")
      .bind("physics.ball_diameter_mm", &f.ball_diameter_mm, "ball diameter, mm");
  schema.read_file(path, /*ignore_unknown=*/true);
  try {
    require_positive("field.length_mm", f.length_mm, kMaxFieldSide_mm);
    require_positive("field.width_mm", f.width_mm, kMaxFieldSide_mm);
    require_non_negative("field.border_mm", f.border_mm, kMaxFieldSide_mm);
    require_non_negative("field.line_width_mm", f.line_width_mm, f.width_mm);
    require_positive("field.goal_width_mm", f.goal_width_mm, f.width_mm);
    require_positive("field.goal_post_diameter_mm", f.goal_post_diameter_mm, f.goal_width_mm);
    require_non_negative("field.goal_box_length_mm", f.goal_box_length_mm, f.length_mm / 2);
    require_non_negative("field.goal_box_width_mm", f.goal_box_width_mm, f.width_mm);
    require_non_negative("field.penalty_area_length_mm", f.penalty_area_length_mm, f.length_mm / 2);
    require_non_negative("field.penalty_area_width_mm", f.penalty_area_width_mm, f.width_mm);
    require_positive("field.penalty_mark_distance_mm", f.penalty_mark_distance_mm, f.length_mm / 2);
    require_non_negative("field.centre_circle_diameter_mm", f.centre_circle_diameter_mm, f.width_mm);
    require_positive("physics.ball_diameter_mm", f.ball_diameter_mm, 1000.f);
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
  return f;
}

} // namespace touchline::python::runswift
