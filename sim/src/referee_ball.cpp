// The referee and the ball: goals, the ball leaving the field, the ball at kick-off.
#include <algorithm>
#include <cmath>
#include <limits>

#include "referee_detail.hpp"
#include "touchline/sim/referee.hpp"

namespace touchline::sim {

namespace {

/// How long ago the ball's centre crossed a line it is now `past` beyond, moving at `v`
/// along that axis away from the field in the direction `outward` (+1 or -1); infinite if it
/// is not moving outwards (it may have bounced back off a wall: no way to tell when).
float time_since_crossing(float past, float v, float outward) {
  const float away = v * outward;
  return away > 0 ? past / away : std::numeric_limits<float>::infinity();
}

} // namespace

bool Referee::check_goal(const RefereeInput& in, RefereeDecision& d) {
  for (int defending : {0, 1}) {
    // Wholly in: even the ball's edge nearest the field is behind the goal line.
    const float towards_field = defending == 0 ? 1.f : -1.f;
    const float nearest_x = in.ball.x_mm + towards_field * ball_radius_mm_;
    if (!field_.in_goal(defending, nearest_x, in.ball.y_mm)) continue;
    const int scorer = 1 - defending;
    ++score_[scorer];
    d.goals.push_back(GoalScored{scorer, in.utime});
    kickoff_team_ = defending; // the conceding team kicks off
    enter(GameState::kReady, in.utime, d);
    d.ball = BallPlacement{BallPlacement::Why::kKickOff, 0.f, 0.f};
    return true;
  }
  return false;
}

std::optional<Referee::BallCrossing> Referee::ball_crossing(const BallTruth& b) const {
  const float hl = field_.half_length(), hw = field_.half_width(), r = ball_radius_mm_;
  const bool past_goal_line = std::fabs(b.x_mm) > hl + r; // wholly past: edges count as in
  const bool past_touchline = std::fabs(b.y_mm) > hw + r;
  if (!past_goal_line && !past_touchline) return std::nullopt;

  const float sx = detail::sign_of(b.x_mm), sy = detail::sign_of(b.y_mm);
  const float since_x = time_since_crossing(std::fabs(b.x_mm) - hl, b.vx_mm_s, sx);
  const float since_y = time_since_crossing(std::fabs(b.y_mm) - hw, b.vy_mm_s, sy);
  BallCrossing crossing;
  crossing.over_touchline = past_touchline;
  if (past_goal_line && past_touchline) {
    // Out over a corner: it left over the line it crossed first (or, with no motion to
    // tell by, the one it is farther past).
    crossing.over_touchline = (std::isinf(since_x) && std::isinf(since_y))
                                  ? std::fabs(b.y_mm) - hw > std::fabs(b.x_mm) - hl
                                  : since_y > since_x;
  }
  if (crossing.over_touchline) {
    const float crossed_x = std::isinf(since_y) ? b.x_mm : b.x_mm - b.vx_mm_s * since_y;
    crossing.x_mm = std::clamp(crossed_x, -hl, hl);
    crossing.y_mm = sy * hw;
  } else {
    const float crossed_y = std::isinf(since_x) ? b.y_mm : b.y_mm - b.vy_mm_s * since_x;
    crossing.x_mm = sx * hl;
    crossing.y_mm = std::clamp(crossed_y, -hw, hw);
  }
  return crossing;
}

// Where the ball goes back, SPL 2011: on the throw-in line (ball_out_inset_mm inside the
// touchline) on the side it left, which ends throw_in_line_end_mm short of each goal line.
// Over a touchline: where it crossed, moved ball_out_setback_mm along x towards the goal of
// the team that touched it last (it loses ground); unknown last touch: where it crossed.
// Over a goal line: at the halfway line when an attacker touched it last (a wide shot
// loses the attack), else at the throw-in line's end by that goal line.
void Referee::check_ball_out(const RefereeInput& in, RefereeDecision& d) const {
  const auto crossing = ball_crossing(in.ball);
  if (!crossing) return;
  const float hl = field_.half_length(), hw = field_.half_width();
  const float line_end_x = std::max(0.f, hl - rules_.throw_in_line_end_mm);
  const float setback = in.last_touch_team == 0   ? -rules_.ball_out_setback_mm
                        : in.last_touch_team == 1 ? rules_.ball_out_setback_mm
                                                  : 0.f;
  BallPlacement put{BallPlacement::Why::kBallOut, 0.f, detail::sign_of(crossing->y_mm) * (hw - rules_.ball_out_inset_mm)};
  if (crossing->over_touchline) {
    put.x_mm = std::clamp(crossing->x_mm + setback, -line_end_x, line_end_x);
  } else {
    const float sx = detail::sign_of(crossing->x_mm);
    const int defending = sx < 0 ? 0 : 1;
    const bool by_attacker = in.last_touch_team == 1 - defending;
    put.x_mm = by_attacker ? 0.f : sx * line_end_x;
  }
  clear_of_robots(in, setback != 0.f ? detail::sign_of(setback) : -detail::sign_of(put.x_mm), line_end_x, put);
  d.ball = put;
}

// Candidates every kClearStepMm along x, nearest first, up to +-limit_x; none clear
// within kClearSteps steps either way (2 m) leaves the spot as it is (a crowd the ball
// cannot avoid).
void Referee::clear_of_robots(const RefereeInput& in, float toward_x, float limit_x, BallPlacement& put) const {
  constexpr float kClearStepMm = 50.f;
  constexpr int kClearSteps = 40;
  const float clearance = rules_.ball_out_clearance_mm;
  if (clearance <= 0.f) return;
  const auto clear = [&](float x) {
    if (std::fabs(x) > limit_x) return false;
    return std::none_of(in.robots.begin(), in.robots.end(), [&](const RobotOnField& r) {
      return std::hypot(r.body.x_mm - x, r.body.y_mm - put.y_mm) < clearance;
    });
  };
  put.x_mm = detail::nearest_along_x(put.x_mm, toward_x, kClearStepMm, kClearSteps, clear).value_or(put.x_mm);
}

// The watch restarts whenever PLAYING starts (kick-off) and while a set play runs (it has
// its own time limit), so only open play counts. A touch restarts the no-touch count; the
// ball leaving a game_stuck_radius_mm circle about where the count began restarts the
// no-progress count.
void Referee::check_game_stuck(const RefereeInput& in, RefereeDecision& d) {
  const bool restart = set_play_ != SetPlay::kNone || state_since_utime_ > progress_utime_;
  if (restart || std::hypot(in.ball.x_mm - progress_x_mm_, in.ball.y_mm - progress_y_mm_) > rules_.game_stuck_radius_mm) {
    progress_x_mm_ = in.ball.x_mm;
    progress_y_mm_ = in.ball.y_mm;
    progress_utime_ = in.utime;
  }
  if (restart || in.touched_by_team[0] || in.touched_by_team[1]) last_ball_touch_utime_ = in.utime;
  const int64_t limit_us = detail::to_us(rules_.game_stuck_s);
  const bool untouched = in.utime - last_ball_touch_utime_ >= limit_us;
  if (!untouched && in.utime - progress_utime_ < limit_us) return;
  kickoff_team_ = in.last_touch_team >= 0 ? 1 - in.last_touch_team : 1 - kickoff_team_;
  d.game_stuck = GameStuck{in.utime, kickoff_team_, untouched};
  enter(GameState::kReady, in.utime, d);
  d.ball = BallPlacement{BallPlacement::Why::kKickOff, 0.f, 0.f};
}

// SPL: the referee puts the ball on the centre spot for every kick-off. The match puts
// it down for the first (where its config says), the referee after a goal and at half
// time, and again at SET if the robots nudged it while walking in READY.
void Referee::replace_ball_for_kickoff(const BallTruth& ball, RefereeDecision& d) const {
  if (!first_kickoff_taken_) return;
  constexpr float kTolerance = 1.f; // mm, mm/s: a ball left alone stays exactly put
  const bool moved = std::hypot(ball.x_mm, ball.y_mm) > kTolerance ||
                     std::hypot(ball.vx_mm_s, ball.vy_mm_s) > kTolerance;
  if (moved) d.ball = BallPlacement{BallPlacement::Why::kKickOff, 0.f, 0.f};
}

} // namespace touchline::sim
