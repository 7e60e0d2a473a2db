#include "touchline/sim/match.hpp"

#include "touchline/angles.hpp"
#include "touchline/parse_number.hpp"
#include "touchline/random.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace touchline::sim {

namespace {
/// In free-running mode a robot may fall behind; more than this much queued motion is
/// dropped from the oldest end, so its lag stays bounded.
constexpr size_t kMaxPendingTicks = 2 * kMaxTicksPerFrame;
} // namespace

Match::Match(const WorldConfig& config, uint64_t seed)
    : config_(config),
      seed_(seed),
      world_(config.field, config.physics, config.match.foot_separation_mm),
      roster_(config.match.team_size),
      perception_(Field(config.field), config.perception, seed),
      comm_(config.comm, seed) {
  if (config.rules.referee)
    referee_.emplace(Field(config.field), config.rules, config.match.team_size, config.physics.ball_diameter_mm);
}

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
  judge(); // the referee starts its clock (INITIAL)
}

void Match::set_external_game(const GameInfo& game, const std::set<RobotId>& penalised) {
  external_game_ = game;
  external_penalised_ = penalised;
}

bool Match::penalised(RobotId id) const {
  if (external_game_) return external_penalised_.count(id) != 0;
  return referee_ && referee_->penalised(id);
}

GameInfo Match::game() const {
  if (external_game_) return *external_game_;
  if (referee_) return referee_->info();
  GameInfo info; // no referee: PLAYING until the duration runs out
  const double left_s = config_.match.duration_s - static_cast<double>(utime()) * 1e-6;
  info.secs_remaining = static_cast<int>(std::max(0.0, std::ceil(left_s)));
  return info;
}

std::vector<Viewer> Match::viewers() const {
  std::vector<Viewer> all;
  for (const auto& [id, robot] : on_field_)
    all.push_back({id, world_.robot(robot.world_index).body, robot.head_yaw_rad, robot.head_pitch_rad});
  return all;
}

SenseFrame Match::sense() {
  SenseFrame frame;
  frame.utime = utime();
  frame.frame = frame_;
  frame.motion_ticks = ticks_in_frame(frame_);
  frame.game = game();
  const BallTruth ball = world_.ball();
  const std::vector<Viewer> all = viewers();
  size_t i = 0;
  for (auto& [id, robot] : on_field_) {
    const Viewer& me = all[i++];
    RobotSense sense;
    sense.id = id;
    sense.active = roster_.find(id)->active;
    sense.truth = me.body;
    sense.ball_x_mm = ball.x_mm;
    sense.ball_y_mm = ball.y_mm;
    sense.seen = perception_.observe(me, all, ball, frame_);
    const SonarReading sonar = perception_.sonar(me, all, frame_);
    sense.sonar_left = sonar.left;
    sense.sonar_right = sonar.right;
    sense.touch = perception_.touch(me, all);
    const float turn_rad =
        robot.frame_start_heading_rad ? normalise_angle(me.body.theta_rad - *robot.frame_start_heading_rad) : 0.f;
    sense.gyro_turn_rad = perception_.gyro_turn(me, turn_rad, frame_);
    sense.penalised = penalised(id);
    sense.fallen = fallen(robot);
    sense.placed = std::exchange(robot.placed, false);
    sense.messages = comm_.receive(id, frame.utime);
    frame.robots.push_back(std::move(sense));
  }
  return frame;
}

std::vector<RobotId> Match::active_robots() const {
  std::vector<RobotId> ids;
  for (const auto& [id, robot] : on_field_)
    if (roster_.find(id)->active) ids.push_back(id);
  return ids;
}

bool plausible(const RobotAct& act) {
  if (act.motion_ticks < 0 || act.motion_ticks > kMaxTicksPerFrame) return false;
  const auto within = [](float value, float limit) { return std::isfinite(value) && std::fabs(value) <= limit; };
  for (int i = 0; i < act.motion_ticks; ++i)
    for (const FootMotion& foot : {act.ticks[static_cast<size_t>(i)].left, act.ticks[static_cast<size_t>(i)].right})
      if (!within(std::hypot(foot.dx_mm, foot.dy_mm), kMaxFootTravelPerTickMm) ||
          !within(foot.dtheta_rad, kMaxFootTurnPerTickRad))
        return false;
  return within(act.head_yaw_rad, kMaxHeadAngleRad) && within(act.head_pitch_rad, kMaxHeadAngleRad);
}

std::vector<RobotId> Match::robots_on_field() const {
  std::vector<RobotId> ids;
  for (const auto& [id, robot] : on_field_) ids.push_back(id);
  return ids;
}

ActOutcome Match::apply(const RobotAct& act, int64_t instance, bool accept_late) {
  Member* member = roster_.find(act.id);
  auto robot = on_field_.find(act.id);
  if (!member || member->instance != instance || robot == on_field_.end()) return ActOutcome::kUnknown;
  if (act.frame > frame_) return ActOutcome::kFuture;
  // A repeat of the answer taken (a shim answers a re-sent sense again) is a duplicate even
  // when it arrives after the world moved on; a late first answer is stale.
  if (act.frame == member->answered_frame) return ActOutcome::kDuplicate;
  if ((act.frame < frame_ && !accept_late) || act.frame < member->answered_frame) return ActOutcome::kStale;
  if (!plausible(act)) return ActOutcome::kImplausible;

  const bool rejoined = !member->active;
  member->active = true;
  member->answered_frame = act.frame;
  ++member->frames_answered;
  member->behaviour_cpu_us_sum += act.behaviour_cpu_us;
  member->behaviour_cpu_us_max = std::max(member->behaviour_cpu_us_max, act.behaviour_cpu_us);
  record_localisation_error(act, *member);
  if (!act.team_message.empty()) {
    comm_.send(act.id, frame_start_utime(act.frame), act.team_message, robots_on_field());
  }
  for (int i = 0; i < act.motion_ticks && i < kMaxTicksPerFrame; ++i)
    robot->second.pending.push_back(act.ticks[static_cast<size_t>(i)]);
  while (robot->second.pending.size() > kMaxPendingTicks) robot->second.pending.pop_front();
  robot->second.head_yaw_rad = act.head_yaw_rad;
  robot->second.head_pitch_rad = act.head_pitch_rad;
  robot->second.chest_led = act.leds;
  return rejoined ? ActOutcome::kRejoined : ActOutcome::kApplied;
}

void Match::record_localisation_error(const RobotAct& act, Member& member) const {
  // The belief answers this frame's sense, taken from the world as it still is. A robot
  // off the field serving a penalty is left out: where it thinks it is does not matter.
  if (penalised(act.id)) return;
  const Pose2D truth = world_.robot(on_field_.at(act.id).world_index).body;
  ++member.localisation_frames;
  member.localisation_sq_mm_sum +=
      std::pow(act.localised.x_mm - truth.x_mm, 2) + std::pow(act.localised.y_mm - truth.y_mm, 2);
  member.localisation_sq_rad_sum += std::pow(normalise_angle(act.localised.theta_rad - truth.theta_rad), 2);
}

void Match::time_out(RobotId id) {
  if (Member* member = roster_.find(id)) {
    member->active = false;
    if (member->answered_frame == frame_) member->answered_frame = frame_ - 1; // its answer is dropped
  }
  if (auto robot = on_field_.find(id); robot != on_field_.end()) robot->second.pending.clear();
}

bool Match::may_move(RobotId id, const OnField& robot) const {
  if (fallen(robot)) return false;
  if (external_game_)
    return !penalised(id) && (external_game_->state == GameState::kReady || external_game_->state == GameState::kPlaying);
  return !referee_ || referee_->may_move(id);
}

bool Match::steps_towards_winner(const OnField& robot, const TickMotion& motion) const {
  if (robot.stopped_by.empty()) return false; // most robots, most ticks: no pose to look up
  const Pose2D body = world_.robot(robot.world_index).body;
  for (RobotId winner : robot.stopped_by)
    if (auto it = on_field_.find(winner); it != on_field_.end() &&
                                          steps_towards(body, motion, world_.robot(it->second.world_index).body))
      return true;
  return false;
}

void Match::advance() {
  for (auto& [id, robot] : on_field_) robot.frame_start_heading_rad = world_.robot(robot.world_index).body.theta_rad;
  std::vector<TickMotion> motions(static_cast<size_t>(world_.robot_count()));
  std::vector<TickMotion> legs(motions.size());
  for (int tick = 0; tick < ticks_in_frame(frame_); ++tick) {
    for (auto& [id, robot] : on_field_) {
      TickMotion& motion = motions[static_cast<size_t>(robot.world_index)];
      TickMotion& leg_motion = legs[static_cast<size_t>(robot.world_index)];
      motion = leg_motion = {};
      if (robot.pending.empty()) continue;
      leg_motion = robot.pending.front(); // the walk moved its legs whether the feet moved or not
      if (may_move(id, robot) && !steps_towards_winner(robot, robot.pending.front()))
        motion = robot.pending.front(); // else the robot's motion is lost
      robot.pending.pop_front();
    }
    world_.step(motions, legs);
    for (int toucher : world_.ball_touches())
      for (const auto& [id, robot] : on_field_)
        if (robot.world_index == toucher) touched_by_team_[static_cast<size_t>(id.team)] = true;
  }
  for (const auto& [id, robot] : on_field_)
    if (Member* member = roster_.find(id); member->answered_frame != frame_) ++member->frames_missed;
  ++frame_;
  judge();
}

void Match::judge() {
  for (auto& [id, robot] : on_field_) robot.stopped_by.clear();
  const std::array<bool, 2> touched = std::exchange(touched_by_team_, {{false, false}});
  if (!referee_) return;
  RefereeInput input;
  input.touched_by_team = touched;
  input.utime = utime();
  input.ball = world_.ball();
  const int toucher = world_.last_ball_touch();
  for (const auto& [id, robot] : on_field_) {
    input.robots.push_back({id, world_.robot(robot.world_index).body, roster_.find(id)->active});
    if (robot.world_index == toucher) input.last_touch_team = id.team;
  }
  carry_out(referee_->update(input));
}

void Match::carry_out(const RefereeDecision& d) {
  for (const StateChange& change : d.state_changes)
    events_.push_back({change.utime, MatchEvent::Kind::kStateChange, {}, -1, to_string(change.to)});
  for (const GoalScored& goal : d.goals)
    events_.push_back({goal.utime, MatchEvent::Kind::kGoal, {}, goal.team, "goal for team " + std::to_string(goal.team)});
  for (const Penalty& penalty : d.penalties) {
    events_.push_back({penalty.since_utime, MatchEvent::Kind::kPenalty, penalty.robot, penalty.robot.team,
                       to_string(penalty.kind)});
    if (penalty.kind == PenaltyKind::kPushing) fall_after_push(penalty.robot);
  }
  for (RobotId id : d.released)
    events_.push_back({utime(), MatchEvent::Kind::kReleased, id, id.team, "back on the field"});
  for (const RobotPlacement& placement : d.placements) {
    auto robot = on_field_.find(placement.robot);
    if (robot == on_field_.end()) continue;
    world_.place_robot(robot->second.world_index, placement.pose);
    robot->second.pending.clear(); // picked up: what it was doing is over
    robot->second.placed = true;
  }
  if (d.ball) {
    world_.place_ball(d.ball->x_mm, d.ball->y_mm);
    if (d.ball->why == BallPlacement::Why::kBallOut)
      events_.push_back({utime(), MatchEvent::Kind::kBallOut, {}, -1, "ball out, put back"});
  }
  for (const SetPlayChange& change : d.set_plays)
    events_.push_back({change.utime, MatchEvent::Kind::kSetPlay, {}, change.team,
                       change.set_play == SetPlay::kNone
                           ? std::string("set play over")
                           : std::string(to_string(change.set_play)) + " for team " + std::to_string(change.team)});
  if (d.game_stuck)
    events_.push_back({d.game_stuck->utime, MatchEvent::Kind::kGameStuck, {}, d.game_stuck->kickoff_team,
                       std::string("game stuck (") + (d.game_stuck->ball_untouched ? "ball untouched" : "ball wedged") +
                           " for " + format_number(config_.rules.game_stuck_s) + " s), kick-off for team " +
                           std::to_string(d.game_stuck->kickoff_team)});
  for (const ContestStop& stop : d.stopped)
    if (auto robot = on_field_.find(stop.robot); robot != on_field_.end()) robot->second.stopped_by.push_back(stop.winner);
}

void Match::fall_after_push(RobotId pusher) {
  // The pushed robot: the nearest opponent of the pusher (the referee names only the pusher).
  const Pose2D at = world_.robot(on_field_.at(pusher).world_index).body;
  OnField* victim = nullptr;
  RobotId victim_id;
  float nearest = config_.rules.collision.contact_distance_mm;
  for (auto& [id, robot] : on_field_) {
    if (id.team == pusher.team) continue;
    const Pose2D body = world_.robot(robot.world_index).body;
    const float d = std::hypot(body.x_mm - at.x_mm, body.y_mm - at.y_mm);
    if (d < nearest) nearest = d, victim = &robot, victim_id = id;
  }
  if (!victim) return;
  auto draws = keyed_draws(seed_, DrawStream::kFall, frame_, draw_id(victim_id.team, victim_id.player),
                           draw_id(pusher.team, pusher.player));
  if (uniform01(draws) >= config_.rules.fall_probability) return;
  victim->fallen_until_utime = utime() + static_cast<int64_t>(config_.rules.getup_s * 1e6);
  victim->pending.clear();
  events_.push_back({utime(), MatchEvent::Kind::kFall, victim_id, victim_id.team, "fell, pushed"});
}

std::vector<MatchEvent> Match::take_events() { return std::exchange(events_, {}); }

TruthFrame Match::truth() const {
  TruthFrame truth;
  truth.utime = utime();
  truth.frame = frame_ - 1;
  truth.ball = world_.ball();
  truth.game = game();
  for (const auto& [id, robot] : on_field_) {
    TruthFrame::Robot r;
    r.truth = world_.robot(robot.world_index);
    r.active = roster_.find(id)->active;
    r.penalised = penalised(id);
    r.fallen = fallen(robot);
    r.head_yaw_rad = robot.head_yaw_rad;
    r.head_pitch_rad = robot.head_pitch_rad;
    r.chest_led = robot.chest_led;
    truth.robots.push_back(r);
  }
  return truth;
}

bool Match::finished() const {
  if (game().state == GameState::kFinished) return true;
  return static_cast<double>(utime()) >= static_cast<double>(config_.match.duration_s) * 1e6;
}

} // namespace touchline::sim
