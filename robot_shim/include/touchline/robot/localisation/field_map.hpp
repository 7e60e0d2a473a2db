#pragma once
#include <string>
// The robot's own map of the field's landmarks, built from the few field dimensions it
// needs (read by the shim from the same config file the world uses). The robot never
// reads the world's geometry: this map and the world's camera must agree only through
// the landmark id convention of touchline/frame.hpp (ObjectKind).
#include <optional>
#include <vector>

#include "touchline/frame.hpp"

namespace touchline::robot::localisation {

/// A point in the field frame (origin at the centre, +x towards the goal team 0
/// attacks, +y left), millimetres.
struct FieldPoint {
  double x_mm = 0;
  double y_mm = 0;
};

/// One landmark the camera can report, and where it stands.
struct Landmark {
  ObjectKind kind = ObjectKind::kGoalPost;
  int id = 0;
  FieldPoint at;
};

/// The field as the robot knows it: the landmark map's dimensions and the rest of the
/// lines a team's code reads (rUNSWift's FIELD_* constants). Defaults: the SPL 2011 field
/// (config/spl2011.ini).
struct FieldMap {
  float length_mm = 6000.f;                ///< between the goal lines, mm
  float width_mm = 4000.f;                 ///< between the touchlines, mm
  float goal_width_mm = 1400.f;            ///< between the goal posts' centres, mm
  float penalty_mark_distance_mm = 1800.f; ///< penalty mark from its goal line, mm
  float border_mm = 700.f;                 ///< carpet beyond the lines, mm
  float line_width_mm = 50.f;              ///< painted line width, mm
  float goal_post_diameter_mm = 100.f;     ///< mm
  float goal_box_length_mm = 600.f;        ///< goal box depth from the goal line, mm
  float goal_box_width_mm = 2200.f;        ///< goal box extent along the goal line, mm
  float penalty_area_length_mm = 0.f;      ///< 0: no separate penalty area (2011); modern: 1650 mm
  float penalty_area_width_mm = 0.f;       ///< modern: 4000 mm
  float centre_circle_diameter_mm = 1200.f; ///< mm
  float ball_diameter_mm = 65.f;           ///< the world's [physics] ball, mm

  /// Where landmark (kind, id) stands: goal posts 0..3 (team 0's goal at -x: left, right
  /// as seen from the field centre, then team 1's at +x), field corners 0..3
  /// (counter-clockwise from (-x, -y)), centre-line ends 0 (-y) and 1 (+y), penalty marks
  /// 0 (team 0's, at -x) and 1. Nothing for the ball, robots or an id out of range.
  std::optional<FieldPoint> landmark(ObjectKind kind, int id) const;

  /// Every landmark, for tests and tools.
  std::vector<Landmark> landmarks() const;
};

/// The field from a world config file's [field] section and its [physics] ball diameter
/// (the same file the world reads; other keys are skipped). Throws touchline::ConfigError,
/// one line naming the file and the key.
FieldMap load_field_map(const std::string& path);

/// Whether `kind` is a fixed landmark (as opposed to the ball or a robot).
bool is_landmark(ObjectKind kind);

} // namespace touchline::robot::localisation
