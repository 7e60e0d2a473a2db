#pragma once
// Field geometry: the SPL pitch, read from the [field] section of a world config.
// Millimetres, field frame (origin at the centre, +x towards the goal team 0 attacks).
#include "touchline/frame.hpp"

namespace touchline::sim {

/// Defaults: the SPL 2011 field (config/spl2011.ini); config/spl2020.ini is 9000 x 6000.
struct FieldDef {
  float length_mm = 6000.f;           ///< between the goal lines (outer edges of the lines)
  float width_mm = 4000.f;            ///< between the touchlines
  float border_mm = 700.f;            ///< carpet beyond the lines, to the boundary walls
  float line_width_mm = 50.f;         ///< painted lines
  float goal_width_mm = 1400.f;       ///< between the posts' centres
  float goal_depth_mm = 500.f;        ///< from the goal line to the net's back
  float goal_post_diameter_mm = 100.f;///< posts are cylinders
  float goal_box_length_mm = 600.f;   ///< goal (keeper) box depth from the goal line
  float goal_box_width_mm = 2200.f;   ///< goal box extent along the goal line
  float penalty_area_length_mm = 0.f; ///< 0: no separate penalty area (2011); modern: 1650
  float penalty_area_width_mm = 0.f;  ///< modern: 4000
  float penalty_mark_distance_mm = 1800.f; ///< from the goal line
  float centre_circle_diameter_mm = 1200.f;
};

/// Derived geometry helpers over a FieldDef.
class Field {
 public:
  explicit Field(const FieldDef& def = {}) : def_(def) {}
  const FieldDef& def() const { return def_; }
  float half_length() const { return def_.length_mm / 2; }
  float half_width() const { return def_.width_mm / 2; }
  /// True inside the outer edges of the field lines.
  bool inside_lines(float x_mm, float y_mm) const;
  /// True on the carpet (inside the boundary walls).
  bool on_carpet(float x_mm, float y_mm) const;
  /// Centre of a post: team 0 defends the goal at -x. `left` as seen from the field centre looking at that goal.
  Pose2D goal_post(int defending_team, bool left) const;
  /// True inside the goal box of the team defending at -x (team 0) or +x (team 1).
  bool in_goal_box(int defending_team, float x_mm, float y_mm) const;
  /// True inside the goal itself (behind the line, between the posts): a goal when the ball is wholly in.
  bool in_goal(int defending_team, float x_mm, float y_mm) const;

 private:
  FieldDef def_;
};

} // namespace touchline::sim
