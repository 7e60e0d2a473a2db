#include "touchline/lcm/codec.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "touchline/angles.hpp"

namespace touchline::transport {

pose2d_t to_lcm(const Pose2D& p) {
  pose2d_t m;
  m.x_mm = p.x_mm;
  m.y_mm = p.y_mm;
  m.theta_rad = p.theta_rad;
  return m;
}

int64_t wall_us() {
  using namespace std::chrono;
  return duration_cast<microseconds>(steady_clock::now().time_since_epoch()).count();
}

namespace {

void check_finite(float value, const char* field, const std::string& what) {
  if (!std::isfinite(value)) throw MalformedMessage(what + ": " + field + " is not finite");
}

Pose2D from_lcm(const pose2d_t& m, const char* field, const std::string& what) {
  check_finite(m.x_mm, field, what);
  check_finite(m.y_mm, field, what);
  check_finite(m.theta_rad, field, what);
  return {m.x_mm, m.y_mm, m.theta_rad};
}

foot_motion_t to_lcm(const FootMotion& f) {
  foot_motion_t m;
  m.dx_mm = f.dx_mm;
  m.dy_mm = f.dy_mm;
  m.dtheta_rad = f.dtheta_rad;
  return m;
}

/// Frame 0..kMaxFrame: frame_start_utime() and ticks_in_frame() of it cannot overflow.
void check_frame(int64_t frame, const std::string& what) {
  if (frame < 0 || frame > kMaxFrame)
    throw MalformedMessage(what + ": frame " + std::to_string(frame) + " is not a frame of a match (0.." +
                           std::to_string(kMaxFrame) + ")");
}

/// Ids that exist for each kind of observation (see ObjectKind in frame.hpp).
void check_observation(const observation_t& seen, const std::string& what) {
  int lowest = 0, highest = 0;
  switch (seen.kind) {
    case static_cast<int8_t>(ObjectKind::kBall): break;
    case static_cast<int8_t>(ObjectKind::kGoalPost):
    case static_cast<int8_t>(ObjectKind::kFieldCorner): highest = 3; break;
    case static_cast<int8_t>(ObjectKind::kCentreLineEnd):
    case static_cast<int8_t>(ObjectKind::kPenaltyMark): highest = 1; break;
    case static_cast<int8_t>(ObjectKind::kTeammate):
    case static_cast<int8_t>(ObjectKind::kOpponent): lowest = 1; highest = kMaxTeamSize; break;
    default: throw MalformedMessage(what + ": unknown observation kind " + std::to_string(seen.kind));
  }
  if (seen.id < lowest || seen.id > highest)
    throw MalformedMessage(what + ": observation of kind " + std::to_string(seen.kind) + " with id " +
                           std::to_string(seen.id) + " (not in " + std::to_string(lowest) + ".." +
                           std::to_string(highest) + ")");
  check_finite(seen.distance_mm, "observation distance_mm", what);
  check_finite(seen.heading_rad, "observation heading_rad", what);
  check_finite(seen.image_x, "observation image_x", what);
}

void check_fraction(float value, const char* field, const std::string& what) {
  if (!(value >= 0.f && value <= 1.f)) throw MalformedMessage(what + ": " + field + " is not in 0..1");
}

FootMotion from_lcm(const foot_motion_t& m, const std::string& what) {
  check_finite(m.dx_mm, "foot dx_mm", what);
  check_finite(m.dy_mm, "foot dy_mm", what);
  check_finite(m.dtheta_rad, "foot dtheta_rad", what);
  return {m.dx_mm, m.dy_mm, m.dtheta_rad};
}

/// A set play names its team; with none the team is not read (the frame says -1).
void check_set_play(int set_play, int team, const std::string& what) {
  if (set_play < 0 || set_play > static_cast<int>(SetPlay::kPenaltyKick))
    throw MalformedMessage(what + ": unknown set_play " + std::to_string(set_play));
  if (set_play != static_cast<int>(SetPlay::kNone) && team != 0 && team != 1)
    throw MalformedMessage(what + ": set_play_team " + std::to_string(team) + " is not 0 or 1");
}

/// A drop-in's team is 0, 1 or -1 (not known); its age is -1 (none yet) or more, and none
/// names no team.
void check_drop_in(int team, int seconds, const std::string& what) {
  if (team < -1 || team > 1)
    throw MalformedMessage(what + ": drop_in_team " + std::to_string(team) + " is not 0, 1 or -1");
  if (seconds < -1) throw MalformedMessage(what + ": drop_in_s " + std::to_string(seconds) + " is below -1");
  if (seconds == -1 && team != -1)
    throw MalformedMessage(what + ": drop_in_team " + std::to_string(team) + " without a drop-in (drop_in_s -1)");
}

} // namespace

std::string act_channel(RobotId id) {
  return "TL_ACT_" + std::to_string(id.team) + "_" + std::to_string(id.player);
}

void check_id(int team, int player, const std::string& what) {
  if (team < 0 || team > 1 || player < 1 || player > kMaxTeamSize)
    throw MalformedMessage(what + ": no such robot (team " + std::to_string(team) + ", player " +
                           std::to_string(player) + ")");
}

sense_t to_lcm(const SenseFrame& frame) {
  sense_t m;
  m.utime = frame.utime;
  m.frame = frame.frame;
  m.motion_ticks = static_cast<int8_t>(frame.motion_ticks);
  m.game_state = static_cast<int8_t>(frame.game.state);
  m.first_half = frame.game.first_half;
  write_game_fields(frame.game, m);
  m.num_robots = static_cast<int16_t>(frame.robots.size());
  for (const RobotSense& r : frame.robots) {
    robot_sense_t s;
    s.team = static_cast<int8_t>(r.id.team);
    s.player = static_cast<int8_t>(r.id.player);
    s.active = r.active;
    s.truth = to_lcm(r.truth);
    s.ball_x_mm = r.ball_x_mm;
    s.ball_y_mm = r.ball_y_mm;
    s.num_seen = static_cast<int16_t>(r.seen.size());
    for (const Observation& o : r.seen) {
      observation_t seen;
      seen.kind = static_cast<int8_t>(o.kind);
      seen.id = static_cast<int8_t>(o.id);
      seen.distance_mm = o.distance_mm;
      seen.heading_rad = o.heading_rad;
      seen.image_x = o.image_x;
      s.seen.push_back(seen);
    }
    s.sonar_left = r.sonar_left;
    s.sonar_right = r.sonar_right;
    s.touch_front_left = r.touch.front_left;
    s.touch_front_right = r.touch.front_right;
    s.touch_left = r.touch.left;
    s.touch_right = r.touch.right;
    s.touch_back = r.touch.back;
    s.gyro_turn_rad = r.gyro_turn_rad;
    s.penalised = r.penalised;
    s.fallen = r.fallen;
    s.placed = r.placed;
    s.num_messages = static_cast<int16_t>(r.messages.size());
    for (const TeamMessageFrame& message : r.messages) {
      team_message_t out;
      out.player = static_cast<int8_t>(message.player);
      out.sent_utime = message.sent_utime;
      out.size = static_cast<int16_t>(message.data.size());
      out.data = message.data;
      s.messages.push_back(out);
    }
    m.robots.push_back(s);
  }
  return m;
}

SenseFrame from_lcm(const sense_t& m) {
  const std::string what = "sense_t frame " + std::to_string(m.frame);
  check_frame(m.frame, what);
  if (m.motion_ticks != ticks_in_frame(m.frame))
    throw MalformedMessage(what + ": motion_ticks " + std::to_string(m.motion_ticks) + ", the frame has " +
                           std::to_string(ticks_in_frame(m.frame)));
  if (m.utime != frame_start_utime(m.frame))
    throw MalformedMessage(what + ": at " + std::to_string(m.utime) + " us is not a frame of a match (it starts at " +
                           std::to_string(frame_start_utime(m.frame)) + " us)");
  if (m.game_state < 0 || m.game_state > static_cast<int8_t>(GameState::kStandby))
    throw MalformedMessage(what + ": unknown game_state " + std::to_string(m.game_state));
  check_set_play(m.set_play, m.set_play_team, what);
  check_drop_in(m.drop_in_team, m.drop_in_s, what);
  if (m.kickoff_team < 0 || m.kickoff_team > 1)
    throw MalformedMessage(what + ": kickoff_team " + std::to_string(m.kickoff_team) + " is not 0 or 1");
  if (m.score[0] < 0 || m.score[1] < 0)
    throw MalformedMessage(what + ": negative score " + std::to_string(m.score[0]) + ":" + std::to_string(m.score[1]));
  SenseFrame frame;
  frame.utime = m.utime;
  frame.frame = m.frame;
  frame.motion_ticks = m.motion_ticks;
  frame.game.state = static_cast<GameState>(m.game_state);
  frame.game.secs_remaining = m.secs_remaining;
  frame.game.first_half = m.first_half;
  frame.game.kickoff_team = m.kickoff_team;
  frame.game.score = {{m.score[0], m.score[1]}};
  frame.game.set_play = static_cast<SetPlay>(m.set_play);
  frame.game.set_play_team = frame.game.set_play == SetPlay::kNone ? -1 : m.set_play_team;
  frame.game.drop_in_team = m.drop_in_team;
  frame.game.drop_in_s = m.drop_in_s;
  std::array<std::array<bool, kMaxTeamSize + 1>, 2> listed{};
  for (const robot_sense_t& s : m.robots) {
    check_id(s.team, s.player, what);
    bool& seen_before = listed[static_cast<size_t>(s.team)][static_cast<size_t>(s.player)];
    if (seen_before)
      throw MalformedMessage(what + ": team " + std::to_string(s.team) + " player " + std::to_string(s.player) +
                             " listed twice");
    seen_before = true;
    RobotSense r;
    r.id = {s.team, s.player};
    r.active = s.active;
    r.truth = from_lcm(s.truth, "truth", what);
    check_finite(s.ball_x_mm, "ball_x_mm", what);
    check_finite(s.ball_y_mm, "ball_y_mm", what);
    r.ball_x_mm = s.ball_x_mm;
    r.ball_y_mm = s.ball_y_mm;
    for (const observation_t& seen : s.seen) {
      check_observation(seen, what);
      r.seen.push_back({static_cast<ObjectKind>(seen.kind), seen.id, seen.distance_mm, seen.heading_rad, seen.image_x});
    }
    check_fraction(s.sonar_left, "sonar_left", what);
    check_fraction(s.sonar_right, "sonar_right", what);
    r.sonar_left = s.sonar_left;
    r.sonar_right = s.sonar_right;
    r.touch.front_left = s.touch_front_left;
    r.touch.front_right = s.touch_front_right;
    r.touch.left = s.touch_left;
    r.touch.right = s.touch_right;
    r.touch.back = s.touch_back;
    check_finite(s.gyro_turn_rad, "gyro_turn_rad", what);
    if (std::fabs(s.gyro_turn_rad) > kPi)
      throw MalformedMessage(what + ": gyro_turn_rad " + std::to_string(s.gyro_turn_rad) + " is not in [-pi, pi]");
    r.gyro_turn_rad = s.gyro_turn_rad;
    r.penalised = s.penalised;
    r.fallen = s.fallen;
    r.placed = s.placed;
    for (const team_message_t& message : s.messages) {
      if (message.player < 1 || message.player > kMaxTeamSize)
        throw MalformedMessage(what + ": team message from player " + std::to_string(message.player));
      if (message.sent_utime < 0 || message.sent_utime > m.utime)
        throw MalformedMessage(what + ": team message sent at " + std::to_string(message.sent_utime) +
                               " us, not in 0.." + std::to_string(m.utime));
      r.messages.push_back({message.player, message.sent_utime, message.data});
    }
    frame.robots.push_back(r);
  }
  return frame;
}

act_t to_lcm(const RobotAct& act, int64_t utime, int64_t instance) {
  act_t m;
  m.utime = utime;
  m.frame = act.frame;
  m.team = static_cast<int8_t>(act.id.team);
  m.player = static_cast<int8_t>(act.id.player);
  m.instance = instance;
  m.motion_ticks = static_cast<int8_t>(act.motion_ticks);
  for (int i = 0; i < act.motion_ticks; ++i) {
    m.left.push_back(to_lcm(act.ticks[static_cast<size_t>(i)].left));
    m.right.push_back(to_lcm(act.ticks[static_cast<size_t>(i)].right));
  }
  m.head_yaw_rad = act.head_yaw_rad;
  m.head_pitch_rad = act.head_pitch_rad;
  m.leds = act.leds;
  m.behaviour_cpu_us = static_cast<int32_t>(act.behaviour_cpu_us);
  m.localised = to_lcm(act.localised);
  std::copy(act.localised_cov_mm2.begin(), act.localised_cov_mm2.end(), m.localised_cov_mm2);
  m.ball_x_mm = act.ball_x_mm;
  m.ball_y_mm = act.ball_y_mm;
  m.ball_lost_frames = act.ball_lost_frames;
  m.team_message_size = static_cast<int16_t>(act.team_message.size());
  m.team_message = act.team_message;
  return m;
}

RobotAct from_lcm(const act_t& m) {
  const std::string what = "act_t frame " + std::to_string(m.frame);
  check_id(m.team, m.player, what);
  check_frame(m.frame, what);
  if (m.behaviour_cpu_us < 0)
    throw MalformedMessage(what + ": behaviour_cpu_us " + std::to_string(m.behaviour_cpu_us) + " is negative");
  if (m.motion_ticks < 0 || m.motion_ticks > kMaxTicksPerFrame)
    throw MalformedMessage(what + ": motion_ticks " + std::to_string(m.motion_ticks) + " not in 0.." +
                           std::to_string(kMaxTicksPerFrame));
  RobotAct act;
  act.id = {m.team, m.player};
  act.frame = m.frame;
  act.motion_ticks = m.motion_ticks;
  for (size_t i = 0; i < static_cast<size_t>(m.motion_ticks); ++i)
    act.ticks[i] = {from_lcm(m.left[i], what), from_lcm(m.right[i], what)};
  check_finite(m.head_yaw_rad, "head_yaw_rad", what);
  check_finite(m.head_pitch_rad, "head_pitch_rad", what);
  act.head_yaw_rad = m.head_yaw_rad;
  act.head_pitch_rad = m.head_pitch_rad;
  act.leds = m.leds;
  act.behaviour_cpu_us = m.behaviour_cpu_us;
  act.localised = from_lcm(m.localised, "localised", what);
  // The belief is the viewer's: passed on unchecked (a diverged filter's NaN is its business).
  std::copy(std::begin(m.localised_cov_mm2), std::end(m.localised_cov_mm2), act.localised_cov_mm2.begin());
  act.ball_x_mm = m.ball_x_mm;
  act.ball_y_mm = m.ball_y_mm;
  act.ball_lost_frames = m.ball_lost_frames;
  act.team_message = m.team_message;
  return act;
}

} // namespace touchline::transport
