#pragma once
// The SPL field constants rUNSWift's code reads from `robot` (FIELD_LENGTH, GOAL_BOX_WIDTH,
// ...), taken from the world's config file ([field], and [physics] for the ball), so their
// code plays on the field the world simulates. Defaults: the world's own (the 2011 field).
#include <string>

namespace touchline::python::runswift {

struct SplFieldDef {
  float length_mm = 6000.f;                 ///< between the goal lines
  float width_mm = 4000.f;                  ///< between the touchlines
  float border_mm = 700.f;                  ///< carpet beyond the lines
  float line_width_mm = 50.f;
  float goal_width_mm = 1400.f;             ///< between the posts' centres
  float goal_post_diameter_mm = 100.f;
  float goal_box_length_mm = 600.f;
  float goal_box_width_mm = 2200.f;
  float penalty_area_length_mm = 0.f;       ///< 0 in 2011 (no separate area): the goal box is used
  float penalty_area_width_mm = 0.f;
  float penalty_mark_distance_mm = 1800.f;  ///< from the goal line
  float centre_circle_diameter_mm = 1200.f;
  float ball_diameter_mm = 65.f;
};

/// Reads [field] and [physics].ball_diameter_mm of a world config ("" : the defaults);
/// other keys are skipped. Throws touchline::ConfigError naming the file.
SplFieldDef load_spl_field(const std::string& path);

} // namespace touchline::python::runswift
