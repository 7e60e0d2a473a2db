// Where the referee puts robots: kick-off positions, the bench, re-entry spots. Every
// position is worked out from team 0's point of view (its half at -x) and turned about
// the centre spot for team 1, so both teams get the same picture.
#include <algorithm>
#include <cmath>

#include "referee_detail.hpp"
#include "touchline/sim/referee.hpp"

namespace touchline::sim {

namespace {
/// The defending team's striker stands this far outside the centre circle, so that its
/// feet (about 100 mm around its body centre) stay out of it.
constexpr float kClearOfCircleMm = 250.f;
} // namespace

Pose2D Referee::kickoff_position(RobotId id, bool kicking_off) const {
  const FieldDef& f = field_.def();
  const float hl = field_.half_length(), hw = field_.half_width();
  const float circle_r = f.centre_circle_diameter_mm / 2;
  // Field players stand in the band from the goal box's front edge (u = 0) to the centre
  // circle's edge (u = 1), so the layout fits any field the config describes.
  const float box_front = -hl + f.goal_box_length_mm;
  const auto band = [&](float u) { return box_front + u * (-circle_r - box_front); };
  Pose2D p;
  switch (id.player) {
    case 1: p = {-hl + f.goal_box_length_mm / 2, 0.f, 0.f}; break; // goalie, mid goal box
    case 2: p = kicking_off ? Pose2D{-circle_r / 2, 0.f, 0.f} : Pose2D{-circle_r - kClearOfCircleMm, 0.f, 0.f}; break;
    case 3: p = {band(0.5f), 0.4f * hw, 0.f}; break;
    case 4: p = {band(0.5f), -0.4f * hw, 0.f}; break;
    case 5: p = {band(0.2f), 0.f, 0.f}; break;
    case 6: p = {band(0.85f), 0.7f * hw, 0.f}; break;
    default: p = {band(0.85f), -0.7f * hw, 0.f}; break;
  }
  return detail::for_team(id.team, p);
}

bool Referee::legal_kickoff_position(RobotId id, const Pose2D& body, bool kicking_off) const {
  const float own_side = id.team == 0 ? -1.f : 1.f;
  if (!field_.inside_lines(body.x_mm, body.y_mm)) return false;
  if (body.x_mm * own_side < 0) return false; // in the opponents' half
  if (id.player != 1 && field_.in_goal_box(id.team, body.x_mm, body.y_mm)) return false;
  const float circle_r = field_.def().centre_circle_diameter_mm / 2;
  if (!kicking_off && std::hypot(body.x_mm, body.y_mm) < circle_r) return false;
  return true;
}

Pose2D Referee::bench_position(RobotId id) const {
  // Half way across the border strip, spread along the own half one spot per player.
  const int spots = std::max(team_size_, id.player) + 1;
  const float x = -field_.half_length() * static_cast<float>(id.player) / static_cast<float>(spots);
  const float y = -(field_.half_width() + field_.def().border_mm / 2);
  return detail::for_team(id.team, Pose2D{x, y, kPi / 2});
}

Pose2D Referee::reentry_position(RobotId id, float ball_x_mm, float ball_y_mm) const {
  const float own_side = id.team == 0 ? -1.f : 1.f;
  const float x = own_side * (field_.half_length() - field_.def().penalty_mark_distance_mm);
  const float hw = field_.half_width();
  const float to_minus = std::hypot(x - ball_x_mm, -hw - ball_y_mm);
  const float to_plus = std::hypot(x - ball_x_mm, hw - ball_y_mm);
  // Farther from the ball; a tie goes to the team's own touchline (team 0: -y).
  const float y = to_minus > to_plus ? -hw : to_plus > to_minus ? hw : own_side * hw;
  return Pose2D{x, y, y < 0 ? kPi / 2 : -kPi / 2};
}

// Re-entering robots must not land on someone: the spot moves along the touchline in
// steps just over the contact distance (so the newcomer is never judged to collide),
// first towards the halfway line, then towards the own goal, staying on the own half.
Pose2D Referee::free_reentry_position(RobotId id, const BallTruth& ball, const Robots& robots) const {
  const Pose2D spot = reentry_position(id, ball.x_mm, ball.y_mm);
  const float contact = rules_.collision.contact_distance_mm;
  const float step = contact + 100.f;
  const float to_centre = id.team == 0 ? 1.f : -1.f;
  const float hl = field_.half_length();
  const auto free = [&](float x) {
    if (x * to_centre > 0 || std::fabs(x) > hl) return false; // off the own half
    return std::none_of(robots.begin(), robots.end(), [&](const RobotOnField& r) {
      return r.id != id && !penalised(r.id) && std::hypot(r.body.x_mm - x, r.body.y_mm - spot.y_mm) < contact;
    });
  };
  Pose2D p = spot;
  p.x_mm = detail::nearest_along_x(spot.x_mm, to_centre, step, 2 * kMaxTeamSize, free).value_or(spot.x_mm);
  return p;
}

// SPL manual placement: at SET, a robot not in a legal kick-off position is put on its
// canonical one. Penalised robots stay on the bench.
void Referee::place_for_kickoff(Robots& robots, RefereeDecision& d) const {
  if (!rules_.manual_placement) return;
  for (RobotOnField& r : robots) {
    if (penalised(r.id)) continue;
    const bool kicking_off = r.id.team == kickoff_team_;
    if (legal_kickoff_position(r.id, r.body, kicking_off)) continue;
    r.body = kickoff_position(r.id, kicking_off);
    d.placements.push_back(RobotPlacement{r.id, r.body});
  }
}

} // namespace touchline::sim
