#include "touchline/sim/landmarks.hpp"

namespace touchline::sim {

std::vector<Landmark> field_landmarks(const Field& field) {
  const float hl = field.half_length(), hw = field.half_width();
  const float mark_x = hl - field.def().penalty_mark_distance_mm;
  std::vector<Landmark> marks;
  for (int team = 0; team < 2; ++team) {
    for (bool left : {true, false}) {
      const Pose2D post = field.goal_post(team, left);
      marks.push_back({ObjectKind::kGoalPost, static_cast<int>(marks.size()), post.x_mm, post.y_mm});
    }
  }
  marks.push_back({ObjectKind::kFieldCorner, 0, -hl, -hw});
  marks.push_back({ObjectKind::kFieldCorner, 1, hl, -hw});
  marks.push_back({ObjectKind::kFieldCorner, 2, hl, hw});
  marks.push_back({ObjectKind::kFieldCorner, 3, -hl, hw});
  marks.push_back({ObjectKind::kCentreLineEnd, 0, 0.f, -hw});
  marks.push_back({ObjectKind::kCentreLineEnd, 1, 0.f, hw});
  marks.push_back({ObjectKind::kPenaltyMark, 0, -mark_x, 0.f});
  marks.push_back({ObjectKind::kPenaltyMark, 1, mark_x, 0.f});
  return marks;
}

} // namespace touchline::sim
