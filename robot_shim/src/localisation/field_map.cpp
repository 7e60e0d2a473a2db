#include "touchline/robot/localisation/field_map.hpp"

#include "touchline/ini.hpp"

namespace touchline::robot::localisation {

namespace {
constexpr int kGoalPosts = 4, kFieldCorners = 4, kCentreLineEnds = 2, kPenaltyMarks = 2;

int landmark_count(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kGoalPost: return kGoalPosts;
    case ObjectKind::kFieldCorner: return kFieldCorners;
    case ObjectKind::kCentreLineEnd: return kCentreLineEnds;
    case ObjectKind::kPenaltyMark: return kPenaltyMarks;
    default: return 0;
  }
}
} // namespace

bool is_landmark(ObjectKind kind) { return landmark_count(kind) > 0; }

std::optional<FieldPoint> FieldMap::landmark(ObjectKind kind, int id) const {
  if (id < 0 || id >= landmark_count(kind)) return std::nullopt;
  const double half_length = length_mm / 2.0, half_width = width_mm / 2.0;
  switch (kind) {
    case ObjectKind::kGoalPost: {
      // Team 0's goal is at -x; looking at it from the centre, its left post is at -y.
      // Looking at team 1's goal (+x), left is +y. Ids 0, 1: team 0's left, right.
      const bool team1_goal = id >= 2;
      const bool left = id % 2 == 0;
      const double side = team1_goal ? 1.0 : -1.0;
      return FieldPoint{side * half_length, side * (left ? 1.0 : -1.0) * goal_width_mm / 2.0};
    }
    case ObjectKind::kFieldCorner: {
      // Counter-clockwise from (-x, -y): (-,-), (+,-), (+,+), (-,+).
      const double xs[kFieldCorners] = {-1, 1, 1, -1};
      const double ys[kFieldCorners] = {-1, -1, 1, 1};
      return FieldPoint{xs[id] * half_length, ys[id] * half_width};
    }
    case ObjectKind::kCentreLineEnd:
      return FieldPoint{0.0, (id == 0 ? -1.0 : 1.0) * half_width};
    case ObjectKind::kPenaltyMark: {
      const double side = id == 0 ? -1.0 : 1.0;
      return FieldPoint{side * (half_length - penalty_mark_distance_mm), 0.0};
    }
    default: return std::nullopt;
  }
}

std::vector<Landmark> FieldMap::landmarks() const {
  std::vector<Landmark> all;
  for (ObjectKind kind : {ObjectKind::kGoalPost, ObjectKind::kFieldCorner, ObjectKind::kCentreLineEnd,
                          ObjectKind::kPenaltyMark})
    for (int id = 0; id < landmark_count(kind); ++id) all.push_back({kind, id, *landmark(kind, id)});
  return all;
}

FieldMap load_field_map(const std::string& path) {
  FieldMap map;
  IniSchema schema("field");
  schema.bind("field.length_mm", &map.length_mm, "between the goal lines, mm")
      .bind("field.width_mm", &map.width_mm, "between the touchlines, mm")
      .bind("field.goal_width_mm", &map.goal_width_mm, "between the posts' centres, mm")
      .bind("field.penalty_mark_distance_mm", &map.penalty_mark_distance_mm, "from the goal line, mm")
      .bind("field.border_mm", &map.border_mm, "carpet beyond the lines, mm")
      .bind("field.line_width_mm", &map.line_width_mm, "line width, mm")
      .bind("field.goal_post_diameter_mm", &map.goal_post_diameter_mm, "post diameter, mm")
      .bind("field.goal_box_length_mm", &map.goal_box_length_mm, "goal box depth, mm")
      .bind("field.goal_box_width_mm", &map.goal_box_width_mm, "goal box width, mm")
      .bind("field.penalty_area_length_mm", &map.penalty_area_length_mm, "penalty area depth, mm")
      .bind("field.penalty_area_width_mm", &map.penalty_area_width_mm, "penalty area width, mm")
      .bind("field.centre_circle_diameter_mm", &map.centre_circle_diameter_mm, "centre circle diameter, mm")
      .bind("physics.ball_diameter_mm", &map.ball_diameter_mm, "ball diameter, mm");
  schema.read_file(path, /*ignore_unknown=*/true);
  try {
    // The world accepts no field longer or wider (sim/src/config.cpp); squares of these
    // stay far inside a float in the filters.
    require_positive("field.length_mm", map.length_mm, kMaxFieldSide_mm);
    require_positive("field.width_mm", map.width_mm, kMaxFieldSide_mm);
    require_positive("field.goal_width_mm", map.goal_width_mm, map.width_mm);
    require_positive("field.penalty_mark_distance_mm", map.penalty_mark_distance_mm, map.length_mm / 2);
    require_non_negative("field.border_mm", map.border_mm, kMaxFieldSide_mm);
    require_non_negative("field.line_width_mm", map.line_width_mm, map.width_mm);
    require_positive("field.goal_post_diameter_mm", map.goal_post_diameter_mm, map.goal_width_mm);
    require_non_negative("field.goal_box_length_mm", map.goal_box_length_mm, map.length_mm / 2);
    require_non_negative("field.goal_box_width_mm", map.goal_box_width_mm, map.width_mm);
    require_non_negative("field.penalty_area_length_mm", map.penalty_area_length_mm, map.length_mm / 2);
    require_non_negative("field.penalty_area_width_mm", map.penalty_area_width_mm, map.width_mm);
    require_non_negative("field.centre_circle_diameter_mm", map.centre_circle_diameter_mm, map.width_mm);
    require_positive("physics.ball_diameter_mm", map.ball_diameter_mm, 1000.f);
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
  return map;
}

} // namespace touchline::robot::localisation
