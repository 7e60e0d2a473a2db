// The referee's set plays (SPL 2020-2022, rules.set_plays): which one a ball out or a
// pushing foul gives, where the ball is put for it, and when it ends.
#include <cmath>

#include "referee_detail.hpp"
#include "touchline/sim/referee.hpp"

namespace touchline::sim {

void Referee::start_set_play(SetPlay set_play, int team, int64_t at, RefereeDecision& d) {
  set_play_ = set_play;
  set_play_team_ = team;
  set_play_until_utime_ = at + detail::to_us(rules_.set_play_s);
  d.set_plays.push_back(SetPlayChange{set_play, team, at});
}

void Referee::end_set_play(int64_t at, RefereeDecision& d) {
  if (set_play_ == SetPlay::kNone) return;
  set_play_ = SetPlay::kNone;
  set_play_team_ = -1;
  d.set_plays.push_back(SetPlayChange{SetPlay::kNone, -1, at});
}

void Referee::check_set_play_over(const RefereeInput& in, RefereeDecision& d) {
  if (set_play_ == SetPlay::kNone) return;
  if (in.touched_by_team[static_cast<size_t>(set_play_team_)] || in.utime >= set_play_until_utime_)
    end_set_play(in.utime, d);
}

// Team 0 defends the goal at -x. A ball out over a goal line touched last by the team
// defending it gives the attackers a corner kick; otherwise (touched by an attacker, or by
// nobody known) the defenders take a goal kick. Over a touchline the opponents of the last
// toucher take a kick-in (nobody known: the team whose half it left from).
void Referee::award_ball_out(const RefereeInput& in, RefereeDecision& d) {
  const auto crossing = ball_crossing(in.ball);
  if (!crossing) return;
  const FieldDef& f = field_.def();
  const float hl = field_.half_length(), hw = field_.half_width();
  const float sx = detail::sign_of(crossing->x_mm), sy = detail::sign_of(crossing->y_mm);
  const int half_owner = crossing->x_mm < 0 ? 0 : 1;
  BallPlacement put{BallPlacement::Why::kSetPlay, 0.f, 0.f};
  if (crossing->over_touchline) {
    const int team = in.last_touch_team >= 0 ? 1 - in.last_touch_team : half_owner;
    put.x_mm = crossing->x_mm;
    put.y_mm = sy * hw;
    start_set_play(SetPlay::kKickIn, team, in.utime, d);
  } else {
    const int defending = sx < 0 ? 0 : 1;
    if (in.last_touch_team == defending) {
      put.x_mm = sx * hl;
      put.y_mm = sy * hw;
      start_set_play(SetPlay::kCornerKick, 1 - defending, in.utime, d);
    } else {
      put.x_mm = sx * (hl - f.goal_box_length_mm);
      put.y_mm = sy * f.goal_box_width_mm / 2;
      start_set_play(SetPlay::kGoalKick, defending, in.utime, d);
    }
  }
  clear_of_robots(in, -detail::sign_of(put.x_mm), hl, put);
  d.ball = put;
}

void Referee::award_foul(const RobotOnField& pusher, int64_t now, RefereeDecision& d) {
  const int fouled = 1 - pusher.id.team;
  if (field_.in_penalty_area(pusher.id.team, pusher.body.x_mm, pusher.body.y_mm)) {
    const float own_goal_side = pusher.id.team == 0 ? -1.f : 1.f;
    const float mark_x = own_goal_side * (field_.half_length() - field_.def().penalty_mark_distance_mm);
    d.ball = BallPlacement{BallPlacement::Why::kSetPlay, mark_x, 0.f};
    start_set_play(SetPlay::kPenaltyKick, fouled, now, d);
  } else {
    start_set_play(SetPlay::kPushingFreeKick, fouled, now, d); // the ball stays where it is
  }
}

} // namespace touchline::sim
