#include "touchline/lcm/snapshot.hpp"

#include <cmath>
#include <limits>

#include "touchline/lcm/codec.hpp"

namespace touchline::transport {

namespace {

namespace AC = api::ActionCommand;

/// Throws MalformedMessage for a snapshot field out of range, naming the snapshot.
class Checker {
 public:
  explicit Checker(const blackboard_snapshot_t& m)
      : what_("blackboard_snapshot_t team " + std::to_string(m.team) + " player " + std::to_string(m.player) +
              " frame " + std::to_string(m.frame)) {}

  template <typename Int>
  Int range(Int value, int64_t lowest, int64_t highest, const char* field) const {
    if (value < lowest || value > highest)
      throw MalformedMessage(what_ + ": " + field + " " + std::to_string(value) + " not in " +
                             std::to_string(lowest) + ".." + std::to_string(highest));
    return value;
  }
  float finite(float value, const char* field) const {
    if (!std::isfinite(value)) throw MalformedMessage(what_ + ": " + field + " is not finite");
    return value;
  }
  const std::string& what() const { return what_; }

 private:
  std::string what_;
};

constexpr int64_t kNoLimit = std::numeric_limits<int64_t>::max();

pose2d_t pose(const api::AbsCoord& c) {
  pose2d_t m;
  m.x_mm = c.x;
  m.y_mm = c.y;
  m.theta_rad = c.theta;
  return m;
}

api::AbsCoord pose(const pose2d_t& m, const Checker& check) {
  return {check.finite(m.x_mm, "pose x_mm"), check.finite(m.y_mm, "pose y_mm"), check.finite(m.theta_rad, "pose theta_rad")};
}

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

AC::Body body(const body_request_t& m, const Checker& check) {
  AC::Body b;
  b.actionType = static_cast<AC::ActionType>(
      check.range(m.action_type, 0, static_cast<int>(AC::ActionType::GOALIE_DIVE_RIGHT), "body action_type"));
  b.forward = check.finite(m.forward_mm_s, "body forward_mm_s");
  b.left = check.finite(m.left_mm_s, "body left_mm_s");
  b.turn = check.finite(m.turn_rad_s, "body turn_rad_s");
  b.power = check.finite(m.power, "body power");
  b.bend = check.finite(m.bend_rad, "body bend_rad");
  b.speed = check.finite(m.speed, "body speed");
  b.foot = static_cast<AC::Foot>(check.range(m.foot, 0, 1, "body foot"));
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

AC::Head head(const head_request_t& m, const Checker& check) {
  AC::Head h;
  h.yaw = check.finite(m.yaw_rad, "head yaw_rad");
  h.pitch = check.finite(m.pitch_rad, "head pitch_rad");
  h.isRelative = m.is_relative;
  h.yawSpeed = check.finite(m.yaw_speed, "head yaw_speed");
  h.pitchSpeed = check.finite(m.pitch_speed, "head pitch_speed");
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
  m.sonar_left = bb.motion.sonarLeft;
  m.sonar_right = bb.motion.sonarRight;
  m.sonar_range_mm = bb.motion.sonarRange_mm;
  m.touch_front_left = bb.motion.touchFrontLeft;
  m.touch_front_right = bb.motion.touchFrontRight;
  m.touch_left = bb.motion.touchLeft;
  m.touch_right = bb.motion.touchRight;
  m.touch_back = bb.motion.touchBack;

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
  m.num_seen_robots = static_cast<int16_t>(bb.vision.robots.size());
  for (const api::SeenObject& seen : bb.vision.robots) {
    observation_t out;
    out.kind = static_cast<int8_t>(seen.teammate ? ObjectKind::kTeammate : ObjectKind::kOpponent);
    out.id = static_cast<int8_t>(seen.id);
    out.distance_mm = seen.rr.distance;
    out.heading_rad = seen.rr.heading;
    out.image_x = 0;
    m.seen_robots.push_back(out);
  }

  const auto& gc = bb.gameController;
  m.game_state = static_cast<int8_t>(gc.state);
  m.gc_team = static_cast<int8_t>(gc.team);
  m.player_number = static_cast<int8_t>(gc.playerNumber);
  m.penalised = gc.penalised;
  m.score[0] = static_cast<int16_t>(gc.score[0]);
  m.score[1] = static_cast<int16_t>(gc.score[1]);
  m.secs_remaining = gc.secsRemaining;
  m.drop_in_team = static_cast<int8_t>(gc.dropInTeam);
  m.drop_in_time = gc.dropInTime;

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
  const Checker check(m);
  check_id(m.team, m.player, check.what());
  check.range(m.frame, 0, kMaxFrame, "frame");
  api::Blackboard bb;
  bb.utime = check.range(m.utime, 0, kNoLimit, "utime");
  bb.behaviour.skill = m.skill;

  bb.motion.odometry = pose(m.odometry, check);
  bb.motion.active = body(m.active, check);
  bb.motion.headYaw = check.finite(m.head_yaw_rad, "head_yaw_rad");
  bb.motion.headPitch = check.finite(m.head_pitch_rad, "head_pitch_rad");
  bb.motion.standing = m.standing;
  bb.motion.ticks = check.range(m.motion_ticks, 0, kNoLimit, "motion_ticks");
  bb.motion.kickPhase = check.range(m.kick_phase, 0, 3, "kick_phase");
  bb.motion.sonarLeft = check.finite(m.sonar_left, "sonar_left");
  bb.motion.sonarRight = check.finite(m.sonar_right, "sonar_right");
  bb.motion.sonarRange_mm = check.finite(m.sonar_range_mm, "sonar_range_mm");
  bb.motion.touchFrontLeft = m.touch_front_left;
  bb.motion.touchFrontRight = m.touch_front_right;
  bb.motion.touchLeft = m.touch_left;
  bb.motion.touchRight = m.touch_right;
  bb.motion.touchBack = m.touch_back;

  auto& loc = bb.localisation;
  loc.robotPos = pose(m.robot_pos, check);
  loc.ballPos = pose(m.ball_pos, check);
  loc.ballPosRR = {check.finite(m.ball_rr_distance_mm, "ball_rr_distance_mm"),
                   check.finite(m.ball_rr_heading_rad, "ball_rr_heading_rad")};
  loc.ballLostCount = check.range(m.ball_lost_count, 0, kNoLimit, "ball_lost_count");
  loc.teamBallPos = pose(m.team_ball_pos, check);

  bb.vision.ballSeen = m.ball_seen;
  bb.vision.ball = {check.finite(m.seen_ball_distance_mm, "seen_ball_distance_mm"),
                    check.finite(m.seen_ball_heading_rad, "seen_ball_heading_rad")};
  bb.vision.frame = check.range(m.vision_frame, 0, kMaxFrame, "vision_frame");
  for (const observation_t& seen : m.seen_robots) {
    check.range(seen.kind, static_cast<int>(ObjectKind::kTeammate), static_cast<int>(ObjectKind::kOpponent),
                "seen robot kind");
    bb.vision.robots.push_back({{check.finite(seen.distance_mm, "seen robot distance_mm"),
                                 check.finite(seen.heading_rad, "seen robot heading_rad")},
                                check.range<int>(seen.id, 1, kMaxTeamSize, "seen robot id"),
                                seen.kind == static_cast<int8_t>(ObjectKind::kTeammate)});
  }

  auto& gc = bb.gameController;
  gc.state = static_cast<api::GameState>(
      check.range(m.game_state, 0, static_cast<int>(api::GameState::STANDBY), "game_state"));
  gc.team = check.range(m.gc_team, 0, 1, "gc_team");
  gc.playerNumber = check.range(m.player_number, 1, kMaxTeamSize, "player_number");
  gc.penalised = m.penalised;
  gc.score = {{check.range(m.score[0], 0, kNoLimit, "score"), check.range(m.score[1], 0, kNoLimit, "score")}};
  gc.secsRemaining = m.secs_remaining;
  gc.dropInTeam = check.range(m.drop_in_team, -1, 1, "drop_in_team");
  gc.dropInTime = check.range(m.drop_in_time, -1, kNoLimit, "drop_in_time");

  for (const team_message_t& message : m.messages)
    bb.receiver.messages.push_back({check.range(message.player, 1, kMaxTeamSize, "team message player"),
                                    check.range(message.sent_utime, 0, kNoLimit, "team message sent_utime"),
                                    message.data});

  bb.behaviour.request.head = head(m.request_head, check);
  bb.behaviour.request.body = body(m.request_body, check);
  bb.behaviour.request.leds.chest = m.request_leds;
  return bb;
}

} // namespace touchline::transport
