// The referee's clock and game states; the checks it runs each update live beside it
// (referee_ball.cpp, referee_penalties.cpp, referee_positions.cpp).
#include "touchline/sim/referee.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "referee_detail.hpp"

namespace touchline::sim {

const char* to_string(PenaltyKind kind) {
  switch (kind) {
    case PenaltyKind::kNone: return "none";
    case PenaltyKind::kPushing: return "pushing";
    case PenaltyKind::kIllegalDefender: return "illegal defender";
    case PenaltyKind::kLeavingField: return "leaving the field";
  }
  return "?";
}

bool RefereeDecision::empty() const {
  return state_changes.empty() && goals.empty() && penalties.empty() && released.empty() &&
         placements.empty() && !ball && stopped.empty() && set_plays.empty() && !game_stuck;
}

Referee::Referee(const Field& field, const RulesDef& rules, int team_size, float ball_diameter_mm)
    : field_(field), rules_(rules), team_size_(team_size), ball_radius_mm_(ball_diameter_mm / 2),
      kickoff_team_(rules.first_kickoff_team) {
  validate(rules_);
  if (team_size < 1 || team_size > kMaxTeamSize)
    throw std::invalid_argument("Referee: team_size must be 1.." + std::to_string(kMaxTeamSize));
  if (!(ball_diameter_mm > 0)) throw std::invalid_argument("Referee: ball_diameter_mm must be > 0");
}

RefereeDecision Referee::update(const RefereeInput& in) {
  if (!started_) {
    started_ = true;
    clock_utime_ = state_since_utime_ = in.utime;
  }
  if (in.utime < clock_utime_)
    throw std::invalid_argument("Referee::update: utime " + std::to_string(in.utime) + " is before " +
                                std::to_string(clock_utime_));
  RefereeDecision d;
  // A working copy in (team, player) order, whatever order the match lists them in;
  // every placement made in this update moves the robot here too, so later checks see
  // it where it will stand rather than where it stood.
  Robots robots = in.robots;
  std::sort(robots.begin(), robots.end(),
            [](const RobotOnField& a, const RobotOnField& b) { return a.id < b.id; });

  record_tracks(in.utime, robots);
  release_served(in.utime, in.ball, robots, d);
  run_clock(in.utime, in.ball, robots, d);

  // The whistle comes first: a ball that goes in after the half ran out is no goal.
  const bool goal = state_ == GameState::kPlaying && check_goal(in, d);
  if (state_ == GameState::kPlaying && !goal) {
    check_set_play_over(in, d);
    if (rules_.ball_out) rules_.set_plays ? award_ball_out(in, d) : check_ball_out(in, d);
    if (d.ball && d.ball->why == BallPlacement::Why::kBallOut) {
      drop_in_team_ = in.last_touch_team;
      drop_in_utime_ = in.utime;
    }
    if (rules_.game_stuck_s > 0 && state_ == GameState::kPlaying) check_game_stuck(in, d);
  }
  const bool robots_walk = state_ == GameState::kReady || state_ == GameState::kSet ||
                           state_ == GameState::kPlaying;
  if (robots_walk && rules_.leaving_field) check_leaving_field(in.utime, robots, d);
  if (state_ == GameState::kPlaying) {
    if (rules_.illegal_defender) check_illegal_defenders(in.utime, robots, d);
    check_collisions(in.utime, in.ball, robots, d);
  } else {
    contact_since_utime_.clear(); // a stoppage ends every contact: the next PLAYING times afresh
  }
  for (const RobotPlacement& p : d.placements) tracks_.erase(p.robot); // picked up: its walk starts again
  return d;
}

GameInfo Referee::info() const {
  GameInfo info;
  info.state = state_;
  info.first_half = first_half_;
  info.kickoff_team = kickoff_team_;
  info.score = score_;
  info.set_play = set_play_;
  info.set_play_team = set_play_team_;
  info.drop_in_team = drop_in_team_;
  info.drop_in_s = drop_in_utime_ < 0 ? -1 : static_cast<int>((clock_utime_ - drop_in_utime_) / 1000000);
  const int64_t left_us = state_ == GameState::kFinished ? 0 : std::max<int64_t>(0, half_us() - played_us_);
  info.secs_remaining = static_cast<int>((left_us + 999999) / 1000000); // whole seconds, rounded up
  return info;
}

std::optional<Penalty> Referee::penalty(RobotId id) const {
  const auto it = penalties_.find(id);
  if (it == penalties_.end()) return std::nullopt;
  return it->second;
}

bool Referee::may_move(RobotId id) const {
  return (state_ == GameState::kReady || state_ == GameState::kPlaying) && !penalised(id);
}

int64_t Referee::half_us() const { return detail::to_us(rules_.half_s); }

// The clock runs piecewise from the last update to `now`: every timed change happens at
// the utime its state ran out, so the states' lengths are exact at any update rate and
// PLAYING time is counted only from the whistle.
void Referee::run_clock(int64_t now, const BallTruth& ball, Robots& robots, RefereeDecision& d) {
  for (;;) {
    const int64_t next = next_timed_event();
    if (next > now) break;
    if (state_ == GameState::kPlaying) played_us_ += next - clock_utime_;
    clock_utime_ = next;
    on_timer(next, ball, robots, d);
  }
  if (state_ == GameState::kPlaying) played_us_ += now - clock_utime_;
  clock_utime_ = now;
}

int64_t Referee::next_timed_event() const {
  switch (state_) {
    case GameState::kInitial: return state_since_utime_ + detail::to_us(rules_.initial_s);
    case GameState::kStandby: return state_since_utime_ + detail::to_us(rules_.standby_s);
    case GameState::kReady: return state_since_utime_ + detail::to_us(rules_.ready_s);
    case GameState::kSet: return state_since_utime_ + detail::to_us(rules_.set_s);
    case GameState::kPlaying: return clock_utime_ + (half_us() - played_us_);
    case GameState::kFinished: break;
  }
  return std::numeric_limits<int64_t>::max();
}

void Referee::on_timer(int64_t at, const BallTruth& ball, Robots& robots, RefereeDecision& d) {
  switch (state_) {
    case GameState::kInitial: enter(rules_.standby_s > 0 ? GameState::kStandby : GameState::kReady, at, d); break;
    case GameState::kStandby: enter(GameState::kReady, at, d); break;
    case GameState::kReady:
      enter(GameState::kSet, at, d);
      place_for_kickoff(robots, d);
      replace_ball_for_kickoff(ball, d);
      break;
    case GameState::kSet:
      enter(GameState::kPlaying, at, d);
      first_kickoff_taken_ = true;
      break;
    case GameState::kPlaying: end_half(at, ball, robots, d); break;
    case GameState::kFinished: break;
  }
}

void Referee::enter(GameState to, int64_t at, RefereeDecision& d) {
  if (to != GameState::kPlaying) end_set_play(at, d); // a set play is part of PLAYING
  d.state_changes.push_back(StateChange{state_, to, at});
  state_ = to;
  state_since_utime_ = at;
}

void Referee::end_half(int64_t at, const BallTruth& ball, Robots& robots, RefereeDecision& d) {
  if (!first_half_) {
    enter(GameState::kFinished, at, d);
    return;
  }
  // Half time: everyone starts the second half on the field (the GameController clears
  // penalties between halves), the other team kicks off, the ball goes to the centre.
  first_half_ = false;
  played_us_ = 0;
  kickoff_team_ = 1 - rules_.first_kickoff_team;
  BallTruth centre = ball;
  centre.x_mm = centre.y_mm = 0;
  std::vector<RobotId> serving;
  for (const auto& [id, p] : penalties_) serving.push_back(id);
  for (RobotId id : serving) release(id, centre, robots, d);
  last_push_utime_.clear();
  d.ball = BallPlacement{BallPlacement::Why::kKickOff, 0.f, 0.f};
  enter(GameState::kInitial, at, d);
}

} // namespace touchline::sim
