// The referee's penalties: detection, removal to the bench, re-entry after removal_s.
#include <algorithm>
#include <cmath>

#include "referee_detail.hpp"
#include "touchline/sim/referee.hpp"

namespace touchline::sim {

bool Referee::may_be_penalised(const RobotOnField& r) const {
  // A crashed robot stands still: whatever it is doing, its code is not doing it.
  return r.active && !penalised(r.id);
}

void Referee::penalise(RobotId id, PenaltyKind kind, int64_t now, RefereeDecision& d) {
  const Penalty p{id, kind, now, now + detail::to_us(rules_.removal_s)};
  penalties_[id] = p;
  d.penalties.push_back(p);
  d.placements.push_back(RobotPlacement{id, bench_position(id)});
}

void Referee::release_served(int64_t now, const BallTruth& ball, Robots& robots, RefereeDecision& d) {
  std::vector<RobotId> served; // in id order: the map's
  for (const auto& [id, p] : penalties_)
    if (p.until_utime <= now) served.push_back(id);
  for (RobotId id : served) release(id, ball, robots, d);
}

void Referee::release(RobotId id, const BallTruth& ball, Robots& robots, RefereeDecision& d) {
  penalties_.erase(id);
  const Pose2D pose = free_reentry_position(id, ball, robots);
  d.released.push_back(id);
  d.placements.push_back(RobotPlacement{id, pose});
  for (RobotOnField& r : robots)
    if (r.id == id) r.body = pose;
}

void Referee::check_leaving_field(int64_t now, const Robots& robots, RefereeDecision& d) {
  const float max_x = field_.half_length() + rules_.leave_field_margin_mm;
  const float max_y = field_.half_width() + rules_.leave_field_margin_mm;
  for (const RobotOnField& r : robots) {
    if (!may_be_penalised(r)) continue;
    if (std::fabs(r.body.x_mm) > max_x || std::fabs(r.body.y_mm) > max_y)
      penalise(r.id, PenaltyKind::kLeavingField, now, d);
  }
}

void Referee::check_illegal_defenders(int64_t now, const Robots& robots, RefereeDecision& d) {
  for (const RobotOnField& r : robots) {
    if (!may_be_penalised(r) || r.id.player == 1) continue; // player 1 is the goalie
    if (field_.in_goal_box(r.id.team, r.body.x_mm, r.body.y_mm))
      penalise(r.id, PenaltyKind::kIllegalDefender, now, d);
  }
}

void Referee::record_tracks(int64_t now, const Robots& robots) {
  const int64_t window_us = detail::to_us(rules_.pushing_window_s);
  for (const RobotOnField& r : robots) {
    auto& track = tracks_[r.id];
    track.emplace_back(now, r.body);
    // Keep the newest pose at or before the window's start (the velocity's base) and after it.
    while (track.size() >= 2 && track[1].first <= now - window_us) track.pop_front();
  }
}

BodyVelocity Referee::velocity_of(const RobotOnField& r, int64_t now, const RefereeDecision& d) const {
  for (const RobotPlacement& p : d.placements)
    if (p.robot == r.id) return {};
  const auto track = tracks_.find(r.id);
  if (track == tracks_.end() || track->second.empty()) return {};
  const auto& [since, from] = track->second.front();
  if (since >= now) return {};
  const float dt_s = static_cast<float>(static_cast<double>(now - since) * 1e-6);
  return {(r.body.x_mm - from.x_mm) / dt_s, (r.body.y_mm - from.y_mm) / dt_s};
}

int Referee::judge_walking_into(int64_t now, const RobotOnField& a, const RobotOnField& b, const CollisionVerdict& v,
                                const RefereeDecision& d) const {
  const auto since = contact_since_utime_.find(std::make_pair(a.id, b.id));
  if (since == contact_since_utime_.end() || now - since->second < detail::to_us(rules_.pushing_min_contact_s))
    return -1;
  return walking_pusher(v, a.body, velocity_of(a, now, d), b.body, velocity_of(b, now, d), rules_.pushing_speed_mm_s);
}

// Thesis 2.2.4 for every pair of robots on the field. Contesting the ball is no foul: of
// two opponents, the robot farther from it is reported stopped (by the nearer). Pushing an
// opponent is penalised, the pusher taken off (rules.pushing_model: the robot the thesis
// names, or the one walking into the other); the pair then gives no other pushing penalty
// for pushing_cooldown_s, so one collision gives one penalty even if the match moves robots
// a frame late or contact distance flickers as feet step. Teammates pushing each other is no
// foul (SPL penalises pushing an opponent).
void Referee::check_collisions(int64_t now, const BallTruth& ball, const Robots& robots, RefereeDecision& d) {
  // Contacts between opponents, timed from their first frame (pushing_min_contact_s).
  std::map<std::pair<RobotId, RobotId>, int64_t> contacts;
  for (size_t i = 0; i < robots.size(); ++i)
    for (size_t j = i + 1; j < robots.size(); ++j) {
      const RobotOnField& a = robots[i];
      const RobotOnField& b = robots[j];
      if (a.id.team == b.id.team || penalised(a.id) || penalised(b.id)) continue;
      if (std::hypot(a.body.x_mm - b.body.x_mm, a.body.y_mm - b.body.y_mm) >= rules_.collision.contact_distance_mm)
        continue;
      const auto key = std::make_pair(a.id, b.id);
      const auto before = contact_since_utime_.find(key);
      contacts[key] = before == contact_since_utime_.end() ? now : before->second;
    }
  contact_since_utime_.swap(contacts);

  const bool walking_into = rules_.pushing_model == "walking_into";
  for (size_t i = 0; i < robots.size(); ++i) {
    for (size_t j = i + 1; j < robots.size(); ++j) {
      const RobotOnField& a = robots[i];
      const RobotOnField& b = robots[j];
      if (penalised(a.id) || penalised(b.id)) continue; // off the field (maybe since this update)
      const CollisionVerdict v = judge_collision(rules_.collision, a.body, b.body, ball.x_mm, ball.y_mm);
      if (v.kind == Collision::kNone) continue;
      if (v.kind == Collision::kContesting) {
        // Only opponents contest the ball: teammates share it out by role, and a teammate's
        // held feet walled the ball in against the contest's winner (a scrum until game stuck).
        if (a.id.team != b.id.team)
          d.stopped.push_back(v.stopped == 0 ? ContestStop{a.id, b.id} : ContestStop{b.id, a.id});
        continue;
      }
      if (a.id.team == b.id.team || !rules_.pushing) continue;
      const int pusher_index = walking_into ? judge_walking_into(now, a, b, v, d) : v.pusher;
      if (pusher_index < 0) continue;
      const RobotOnField& pusher = pusher_index == 0 ? a : b;
      if (!pusher.active) continue;
      const auto key = std::make_pair(a.id, b.id); // robots are sorted: a.id < b.id
      const auto last = last_push_utime_.find(key);
      if (last != last_push_utime_.end() && now - last->second < detail::to_us(rules_.pushing_cooldown_s))
        continue;
      penalise(pusher.id, PenaltyKind::kPushing, now, d);
      last_push_utime_[key] = now;
      if (rules_.set_plays) award_foul(pusher, now, d);
    }
  }
}

} // namespace touchline::sim
