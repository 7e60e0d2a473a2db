#include "touchline/sim/field.hpp"

#include <cmath>

namespace touchline::sim {

namespace {
/// +1 for the goal at +x (team 1 defends it), -1 for the goal at -x (team 0).
float goal_side(int defending_team) { return defending_team == 0 ? -1.f : 1.f; }
} // namespace

float Field::goal_line_x(int defending_team) const {
  return goal_side(defending_team) * half_length();
}

bool Field::inside_lines(float x_mm, float y_mm) const {
  return std::fabs(x_mm) <= half_length() && std::fabs(y_mm) <= half_width();
}

bool Field::on_carpet(float x_mm, float y_mm) const {
  return std::fabs(x_mm) <= half_length() + def_.border_mm &&
         std::fabs(y_mm) <= half_width() + def_.border_mm;
}

Pose2D Field::goal_post(int defending_team, bool left) const {
  // Looking at the -x goal from the centre, left is -y; looking at the +x goal, left is +y.
  const float y = goal_side(defending_team) * (left ? 1.f : -1.f) * def_.goal_width_mm / 2;
  return Pose2D{goal_line_x(defending_team), y, 0.f};
}

bool Field::in_goal_box(int defending_team, float x_mm, float y_mm) const {
  const float depth = -goal_side(defending_team) * (x_mm - goal_line_x(defending_team));
  return depth >= 0 && depth <= def_.goal_box_length_mm &&
         std::fabs(y_mm) <= def_.goal_box_width_mm / 2;
}

bool Field::in_penalty_area(int defending_team, float x_mm, float y_mm) const {
  if (def_.penalty_area_length_mm <= 0 || def_.penalty_area_width_mm <= 0) return in_goal_box(defending_team, x_mm, y_mm);
  const float depth = -goal_side(defending_team) * (x_mm - goal_line_x(defending_team));
  return depth >= 0 && depth <= def_.penalty_area_length_mm && std::fabs(y_mm) <= def_.penalty_area_width_mm / 2;
}

bool Field::in_goal(int defending_team, float x_mm, float y_mm) const {
  // Positive behind the goal line, towards the net's back.
  const float behind = goal_side(defending_team) * (x_mm - goal_line_x(defending_team));
  return behind > 0 && behind <= def_.goal_depth_mm && std::fabs(y_mm) <= def_.goal_width_mm / 2;
}

} // namespace touchline::sim
