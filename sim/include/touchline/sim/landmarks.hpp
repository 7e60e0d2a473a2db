#pragma once
// The fixed field features a robot's camera reports and a localisation filter can use,
// with their ids as frame.hpp defines them. Field frame, millimetres; posts, corners and
// line ends sit on the Field's lines (x = +-length/2, y = +-width/2), like Field::goal_post.
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/sim/field.hpp"

namespace touchline::sim {

struct Landmark {
  ObjectKind kind = ObjectKind::kGoalPost;
  int id = 0;
  float x_mm = 0, y_mm = 0;
};

/// Goal posts 0..3 (team 0's goal left, right as seen from the field centre, then team
/// 1's), field corners 0..3 (counter-clockwise from (-x, -y)), centre-line ends 0 (-y)
/// and 1 (+y), penalty marks 0 (team 0's, at -x) and 1: always in this order.
std::vector<Landmark> field_landmarks(const Field& field);

} // namespace touchline::sim
