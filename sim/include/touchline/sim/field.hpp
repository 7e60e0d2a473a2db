#pragma once
// Field geometry: the SPL pitch, read from the [field] section of a world config.
// Millimetres, field frame (origin at the centre, +x towards the goal team 0 attacks).
// The goal lines are x = +-length/2 and the touchlines y = +-width/2 (the lines' outer
// edges); the goal posts stand centred on the goal lines, the nets behind them.
#include "touchline/frame.hpp"

namespace touchline::sim {

/// Defaults: the SPL 2011 field (config/spl2011.ini); config/spl2020.ini is 9000 x 6000.
struct FieldDef {
  float length_mm = 6000.f;           ///< between the goal lines (outer edges of the lines)
  float width_mm = 4000.f;            ///< between the touchlines
  float border_mm = 700.f;            ///< carpet beyond the lines, to the boundary walls (> goal_depth_mm)
  float line_width_mm = 50.f;         ///< painted lines
  float goal_width_mm = 1400.f;       ///< between the posts' centres
  float goal_depth_mm = 500.f;        ///< from the goal line to the net's back
  float goal_post_diameter_mm = 100.f;///< posts are cylinders
  float goal_box_length_mm = 600.f;   ///< goal (keeper) box depth from the goal line
  float goal_box_width_mm = 2200.f;   ///< goal box extent along the goal line
  float penalty_area_length_mm = 0.f; ///< 0: no separate penalty area (2011); modern: 1650
  float penalty_area_width_mm = 0.f;  ///< modern: 4000
  float penalty_mark_distance_mm = 1800.f; ///< from the goal line
  float centre_circle_diameter_mm = 1200.f; ///< mm
};

/// Derived geometry helpers over a FieldDef.
class Field {
 public:
  explicit Field(const FieldDef& def = {}) : def_(def) {}
  const FieldDef& def() const { return def_; }
  float half_length() const { return def_.length_mm / 2; }
  float half_width() const { return def_.width_mm / 2; }
  /// x of the goal line of the goal `defending_team` defends: -half_length for team 0.
  float goal_line_x(int defending_team) const;
  /// True inside the outer edges of the field lines (the edges themselves count as inside).
  bool inside_lines(float x_mm, float y_mm) const;
  /// True on the carpet (inside the boundary walls).
  bool on_carpet(float x_mm, float y_mm) const;
  /// Centre of a post: team 0 defends the goal at -x. `left` as seen from the field centre looking at that goal.
  Pose2D goal_post(int defending_team, bool left) const;
  /// True inside the goal box (goal_box_length x goal_box_width, from the goal line into
  /// the field) of the team defending at -x (team 0) or +x (team 1). Edges count as inside.
  bool in_goal_box(int defending_team, float x_mm, float y_mm) const;
  /// True inside the penalty area (penalty_area_length x penalty_area_width, as the goal
  /// box); a field without one (2011: 0) has the goal box serve as it, as that rule book did.
  bool in_penalty_area(int defending_team, float x_mm, float y_mm) const;
  /// True inside the goal itself: strictly behind the goal line, at most goal_depth_mm
  /// behind it, and between the side nets (|y| <= goal_width/2). For a point; a goal is
  /// scored when the ball's centre is in by more than its radius.
  bool in_goal(int defending_team, float x_mm, float y_mm) const;

 private:
  FieldDef def_;
};

} // namespace touchline::sim
