#include "touchline/sim/match.hpp"

#include <algorithm>

namespace touchline::sim {

namespace {
/// In free-running mode a robot may fall behind; more than this much queued motion is
/// dropped from the oldest end, so its lag stays bounded.
constexpr size_t kMaxPendingTicks = 2 * kMaxTicksPerFrame;
} // namespace

Match::Match(const WorldConfig& config)
    : config_(config),
      world_(config.field, config.physics, config.match.foot_separation_mm),
      roster_(config.match.team_size) {}

JoinReply Match::join(RobotId id, int64_t instance, int pid) {
  JoinReply reply = roster_.join(id, instance, pid);
  if (reply.accepted && started_ && !on_field_.count(id)) place(id);
  return reply;
}

void Match::place(RobotId id) {
  OnField robot;
  robot.world_index = world_.add_robot(id, initial_pose(world_.field(), roster_.team_size(), id));
  on_field_[id] = robot;
}

void Match::start() {
  for (const auto& [id, member] : roster_.members()) place(id); // std::map: (team, player) order
  world_.place_ball(config_.match.ball_start_x_mm, config_.match.ball_start_y_mm);
  started_ = true;
}

SenseFrame Match::sense() const {
  SenseFrame frame;
  frame.utime = utime();
  frame.frame = frame_;
  frame.motion_ticks = ticks_in_frame(frame_);
  frame.game_state = GameState::kPlaying;
  const BallTruth ball = world_.ball();
  for (const auto& [id, robot] : on_field_) {
    RobotSense sense;
    sense.id = id;
    sense.active = roster_.find(id)->active;
    sense.truth = world_.robot(robot.world_index).body;
    sense.ball_x_mm = ball.x_mm;
    sense.ball_y_mm = ball.y_mm;
    frame.robots.push_back(sense);
  }
  return frame;
}

std::vector<RobotId> Match::active_robots() const {
  std::vector<RobotId> ids;
  for (const auto& [id, robot] : on_field_)
    if (roster_.find(id)->active) ids.push_back(id);
  return ids;
}

ActOutcome Match::apply(const RobotAct& act, int64_t instance, bool accept_late) {
  Member* member = roster_.find(act.id);
  auto robot = on_field_.find(act.id);
  if (!member || member->instance != instance || robot == on_field_.end()) return ActOutcome::kUnknown;
  const bool on_time = act.frame == frame_;
  if (!on_time && !(accept_late && act.frame < frame_)) return ActOutcome::kStale;

  const bool rejoined = !member->active;
  member->active = true;
  ++member->frames_answered;
  member->behaviour_cpu_us_sum += act.behaviour_cpu_us;
  member->behaviour_cpu_us_max = std::max(member->behaviour_cpu_us_max, act.behaviour_cpu_us);
  for (int i = 0; i < act.motion_ticks && i < kMaxTicksPerFrame; ++i)
    robot->second.pending.push_back({act.left[i], act.right[i]});
  while (robot->second.pending.size() > kMaxPendingTicks) robot->second.pending.pop_front();
  robot->second.head_yaw_rad = act.head_yaw_rad;
  robot->second.head_pitch_rad = act.head_pitch_rad;
  return rejoined ? ActOutcome::kRejoined : ActOutcome::kApplied;
}

void Match::time_out(RobotId id) {
  if (Member* member = roster_.find(id)) {
    member->active = false;
    ++member->frames_missed;
  }
  if (auto robot = on_field_.find(id); robot != on_field_.end()) robot->second.pending.clear();
}

void Match::advance() {
  std::vector<TickMotion> motions(static_cast<size_t>(world_.robot_count()));
  for (int tick = 0; tick < ticks_in_frame(frame_); ++tick) {
    for (auto& [id, robot] : on_field_) {
      TickMotion& motion = motions[static_cast<size_t>(robot.world_index)];
      motion = {};
      if (!robot.pending.empty()) {
        motion = robot.pending.front();
        robot.pending.pop_front();
      }
    }
    world_.step(motions);
  }
  ++frame_;
}

TruthFrame Match::truth() const {
  TruthFrame truth;
  truth.utime = utime();
  truth.frame = frame_ - 1;
  truth.ball = world_.ball();
  for (const auto& [id, robot] : on_field_) {
    TruthFrame::Robot r;
    r.truth = world_.robot(robot.world_index);
    r.active = roster_.find(id)->active;
    r.head_yaw_rad = robot.head_yaw_rad;
    r.head_pitch_rad = robot.head_pitch_rad;
    truth.robots.push_back(r);
  }
  return truth;
}

bool Match::finished() const {
  return static_cast<double>(utime()) >= static_cast<double>(config_.match.duration_s) * 1e6;
}

} // namespace touchline::sim
