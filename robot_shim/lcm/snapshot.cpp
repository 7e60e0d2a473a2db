#include "touchline/lcm/snapshot.hpp"

namespace touchline::transport {

namespace {

namespace AC = api::ActionCommand;

pose2d_t pose(const api::AbsCoord& c) {
  pose2d_t m;
  m.x_mm = c.x;
  m.y_mm = c.y;
  m.theta_rad = c.theta;
  return m;
}

api::AbsCoord pose(const pose2d_t& m) { return {m.x_mm, m.y_mm, m.theta_rad}; }

body_request_t body(const AC::Body& b) {
  body_request_t m;
  m.action_type = static_cast<int8_t>(b.actionType);
  m.forward_mm_s = b.forward;
  m.left_mm_s = b.left;
  m.turn_rad_s = b.turn;
  m.power = b.power;
  m.bend_rad = b.bend;
  m.speed = b.speed;
  m.foot = static_cast<int8_t>(b.foot);
  return m;
}

AC::Body body(const body_request_t& m) {
  AC::Body b;
  b.actionType = static_cast<AC::ActionType>(m.action_type);
  b.forward = m.forward_mm_s;
  b.left = m.left_mm_s;
  b.turn = m.turn_rad_s;
  b.power = m.power;
  b.bend = m.bend_rad;
  b.speed = m.speed;
  b.foot = static_cast<AC::Foot>(m.foot);
  return b;
}

head_request_t head(const AC::Head& h) {
  head_request_t m;
  m.yaw_rad = h.yaw;
  m.pitch_rad = h.pitch;
  m.is_relative = h.isRelative;
  m.yaw_speed = h.yawSpeed;
  m.pitch_speed = h.pitchSpeed;
  return m;
}

AC::Head head(const head_request_t& m) {
  AC::Head h;
  h.yaw = m.yaw_rad;
  h.pitch = m.pitch_rad;
  h.isRelative = m.is_relative;
  h.yawSpeed = m.yaw_speed;
  h.pitchSpeed = m.pitch_speed;
  return h;
}

} // namespace

std::string snapshot_channel(RobotId id) {
  return "TL_BLACKBOARD_" + std::to_string(id.team) + "_" + std::to_string(id.player);
}

blackboard_snapshot_t to_snapshot(const api::Blackboard& bb, RobotId id, int64_t frame) {
  blackboard_snapshot_t m;
  m.utime = bb.utime;
  m.frame = frame;
  m.team = static_cast<int8_t>(id.team);
  m.player = static_cast<int8_t>(id.player);
  m.skill = bb.behaviour.skill;

  m.odometry = pose(bb.motion.odometry);
  m.active = body(bb.motion.active);
  m.head_yaw_rad = bb.motion.headYaw;
  m.head_pitch_rad = bb.motion.headPitch;
  m.standing = bb.motion.standing;
  m.motion_ticks = bb.motion.ticks;
  m.kick_phase = static_cast<int8_t>(bb.motion.kickPhase);

  const auto& loc = bb.localisation;
  m.robot_pos = pose(loc.robotPos);
  m.ball_pos = pose(loc.ballPos);
  m.ball_rr_distance_mm = loc.ballPosRR.distance;
  m.ball_rr_heading_rad = loc.ballPosRR.heading;
  m.ball_lost_count = loc.ballLostCount;
  m.team_ball_pos = pose(loc.teamBallPos);

  m.ball_seen = bb.vision.ballSeen;
  m.seen_ball_distance_mm = bb.vision.ball.distance;
  m.seen_ball_heading_rad = bb.vision.ball.heading;
  m.vision_frame = bb.vision.frame;

  const auto& gc = bb.gameController;
  m.game_state = static_cast<int8_t>(gc.state);
  m.gc_team = static_cast<int8_t>(gc.team);
  m.player_number = static_cast<int8_t>(gc.playerNumber);
  m.penalised = gc.penalised;
  m.score[0] = static_cast<int16_t>(gc.score[0]);
  m.score[1] = static_cast<int16_t>(gc.score[1]);
  m.secs_remaining = gc.secsRemaining;

  m.num_messages = static_cast<int16_t>(bb.receiver.messages.size());
  for (const api::TeamMessage& message : bb.receiver.messages) {
    team_message_t out;
    out.player = static_cast<int8_t>(message.playerNumber);
    out.sent_utime = message.utime;
    out.size = static_cast<int16_t>(message.data.size());
    out.data = message.data;
    m.messages.push_back(out);
  }

  m.request_head = head(bb.behaviour.request.head);
  m.request_body = body(bb.behaviour.request.body);
  m.request_leds = bb.behaviour.request.leds.chest;
  return m;
}

api::Blackboard from_snapshot(const blackboard_snapshot_t& m) {
  api::Blackboard bb;
  bb.utime = m.utime;
  bb.behaviour.skill = m.skill;

  bb.motion.odometry = pose(m.odometry);
  bb.motion.active = body(m.active);
  bb.motion.headYaw = m.head_yaw_rad;
  bb.motion.headPitch = m.head_pitch_rad;
  bb.motion.standing = m.standing;
  bb.motion.ticks = m.motion_ticks;
  bb.motion.kickPhase = m.kick_phase;

  auto& loc = bb.localisation;
  loc.robotPos = pose(m.robot_pos);
  loc.ballPos = pose(m.ball_pos);
  loc.ballPosRR = {m.ball_rr_distance_mm, m.ball_rr_heading_rad};
  loc.ballLostCount = m.ball_lost_count;
  loc.teamBallPos = pose(m.team_ball_pos);

  bb.vision.ballSeen = m.ball_seen;
  bb.vision.ball = {m.seen_ball_distance_mm, m.seen_ball_heading_rad};
  bb.vision.frame = m.vision_frame;

  auto& gc = bb.gameController;
  gc.state = static_cast<api::GameState>(m.game_state);
  gc.team = m.gc_team;
  gc.playerNumber = m.player_number;
  gc.penalised = m.penalised;
  gc.score = {{m.score[0], m.score[1]}};
  gc.secsRemaining = m.secs_remaining;

  for (const team_message_t& message : m.messages)
    bb.receiver.messages.push_back({message.player, message.sent_utime, message.data});

  bb.behaviour.request.head = head(m.request_head);
  bb.behaviour.request.body = body(m.request_body);
  bb.behaviour.request.leds.chest = m.request_leds;
  return bb;
}

} // namespace touchline::transport
