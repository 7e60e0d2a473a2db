#include "samples.hpp"

#include "touchline/lcm/codec.hpp"
#include "touchline/lcm/snapshot.hpp"
#include "touchline/gamecontroller/packet.hpp"

namespace touchline::fuzz {

namespace {

RobotAct act(int ticks) {
  RobotAct a;
  a.id = {1, 4};
  a.frame = 77;
  a.motion_ticks = ticks;
  for (size_t i = 0; i < static_cast<size_t>(ticks); ++i) a.ticks[i] = {{1.f, 0.5f, 0.01f}, {1.f, 0.5f, 0.01f}};
  a.team_message = {9, 8, 7};
  return a;
}

SenseFrame sense_frame() {
  SenseFrame f;
  f.frame = 8;
  f.utime = frame_start_utime(8);
  f.motion_ticks = ticks_in_frame(8);
  for (int player = 1; player <= 2; ++player) {
    RobotSense r;
    r.id = {player - 1, player};
    r.seen = {{ObjectKind::kBall, 0, 900, 0.1f, 0.5f}, {ObjectKind::kFieldCorner, 2, 3000, -1.f, 0.1f}};
    r.messages = {{2, frame_start_utime(7), {1, 2}}};
    f.robots.push_back(r);
  }
  return f;
}

Bytes gamecontroller_packet(int version, int state, int kicking_team) {
  namespace gc = sim::gamecontroller;
  Bytes b(gc::kPacketSize, 0);
  for (size_t i = 0; i < 4; ++i) b[i] = static_cast<uint8_t>(gc::kHeader[i]);
  b[4] = static_cast<uint8_t>(version);
  b[6] = 5;  // playersPerTeam
  b[10] = static_cast<uint8_t>(state);
  b[12] = 1; // firstHalf
  b[13] = static_cast<uint8_t>(kicking_team);
  b[14] = 0x58, b[15] = 0x02; // secsRemaining 600, little-endian
  const size_t teams_at = 18, team_size = 10 + 2 * gc::kMaxNumPlayers;
  b[teams_at] = 5;
  b[teams_at + team_size] = 12;
  b[teams_at + 4] = 2;                    // team 5 scored twice
  b[teams_at + 10 + 2] = 1;               // team 5's player 2: penalised ...
  b[teams_at + 10 + 3] = 30;              // ... for 30 s
  b[teams_at + team_size + 10 + 12] = 14; // team 12's player 7: substitute
  return b;
}

} // namespace

std::vector<pose2d_t> samples(Tag<pose2d_t>) { return {transport::to_lcm(Pose2D{120, -40, 1.5f})}; }

std::vector<foot_motion_t> samples(Tag<foot_motion_t>) { return {foot_motion_t{2.5f, -1.f, 0.01f}}; }

std::vector<observation_t> samples(Tag<observation_t>) { return {observation_t{1, 2, 1500, 0.3f, 0.6f}}; }

std::vector<team_message_t> samples(Tag<team_message_t>) {
  team_message_t empty{};
  empty.player = 2;
  team_message_t some = empty;
  some.data = {1, 2, 3, 4};
  some.size = 4;
  return {empty, some};
}

std::vector<act_t> samples(Tag<act_t>) {
  return {transport::to_lcm(act(4), frame_start_utime(77), 5), transport::to_lcm(act(0), frame_start_utime(77), 5)};
}

std::vector<sense_t> samples(Tag<sense_t>) { return {transport::to_lcm(sense_frame()), transport::to_lcm(SenseFrame{})}; }

std::vector<robot_sense_t> samples(Tag<robot_sense_t>) { return {transport::to_lcm(sense_frame()).robots[0]}; }

std::vector<robot_truth_t> samples(Tag<robot_truth_t>) {
  robot_truth_t t{};
  t.team = 1;
  t.player = 3;
  t.body = transport::to_lcm(Pose2D{10, 20, 0.3f});
  return {t};
}

std::vector<world_truth_t> samples(Tag<world_truth_t>) {
  world_truth_t w{};
  w.frame = 8;
  w.robots = {samples(Tag<robot_truth_t>{})[0], samples(Tag<robot_truth_t>{})[0]};
  w.num_robots = 2;
  return {w, world_truth_t{}};
}

std::vector<game_state_t> samples(Tag<game_state_t>) {
  game_state_t g{};
  g.state = game_state_t::PLAYING;
  g.secs_remaining = 300;
  return {g};
}

std::vector<match_config_t> samples(Tag<match_config_t>) {
  match_config_t m{};
  m.types_version = match_config_t::TYPES_VERSION;
  m.team_size = 4;
  m.field_length_mm = 9000;
  m.field_width_mm = 6000;
  m.ball_diameter_mm = 100;
  return {m};
}

std::vector<join_t> samples(Tag<join_t>) { return {join_t{0, 1, 3, 424242, 1000}}; }

std::vector<join_reply_t> samples(Tag<join_reply_t>) {
  join_reply_t accepted{};
  accepted.accepted = 1;
  join_reply_t refused = accepted;
  refused.accepted = 0;
  refused.reason = "team 1 player 3 is taken";
  return {accepted, refused};
}

std::vector<match_event_t> samples(Tag<match_event_t>) {
  match_event_t e{};
  e.kind = match_event_t::GOAL;
  e.text = "goal";
  return {e};
}

std::vector<robot_status_t> samples(Tag<robot_status_t>) {
  robot_status_t s{};
  s.state = robot_status_t::JOINED;
  s.detail = "joined (pid 1000)";
  return {s};
}

std::vector<body_request_t> samples(Tag<body_request_t>) { return {body_request_t{2, 200, 0, 0.5f, 0, 0, 1, 0}}; }

std::vector<head_request_t> samples(Tag<head_request_t>) { return {head_request_t{0.5f, 0.1f, 0, 1, 1}}; }

std::vector<blackboard_snapshot_t> samples(Tag<blackboard_snapshot_t>) {
  api::Blackboard bb;
  bb.behaviour.skill = "GoToBall";
  bb.receiver.messages = {{2, 1000, {1, 2, 3}}, {3, 2000, {}}};
  bb.motion.sonarLeft = 0.5f;
  bb.vision.robots = {{{700, 0.1f}, 3, true}, {{400, -0.2f}, 5, false}};
  return {transport::to_snapshot(bb, {0, 2}, 30), transport::to_snapshot(api::Blackboard{}, {1, 1}, 0)};
}

std::vector<Bytes> gamecontroller_samples() {
  namespace gc = sim::gamecontroller;
  return {gamecontroller_packet(15, 3, 5), gamecontroller_packet(18, gc::kStateStandby, gc::kKickingTeamNone),
          gamecontroller_packet(18, 1, 12)};
}

} // namespace touchline::fuzz
