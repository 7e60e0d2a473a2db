#include "touchline/lcm/world_messages.hpp"

#include <cstdint>

#include "touchline/lcm/codec.hpp"

namespace touchline::transport {

world_truth_t to_msg(const sim::TruthFrame& truth) {
  world_truth_t m;
  m.utime = truth.utime;
  m.frame = truth.frame;
  m.ball_x_mm = truth.ball.x_mm;
  m.ball_y_mm = truth.ball.y_mm;
  m.ball_vx_mm_s = truth.ball.vx_mm_s;
  m.ball_vy_mm_s = truth.ball.vy_mm_s;
  m.num_robots = static_cast<int16_t>(truth.robots.size());
  for (const auto& r : truth.robots) {
    robot_truth_t t;
    t.team = static_cast<int8_t>(r.truth.id.team);
    t.player = static_cast<int8_t>(r.truth.id.player);
    t.active = r.active;
    t.penalised = r.penalised;
    t.fallen = r.fallen;
    t.body = to_lcm(r.truth.body);
    t.left_foot = to_lcm(r.truth.left_foot);
    t.right_foot = to_lcm(r.truth.right_foot);
    t.head_yaw_rad = r.head_yaw_rad;
    t.head_pitch_rad = r.head_pitch_rad;
    t.chest_led = r.chest_led;
    m.robots.push_back(t);
  }
  return m;
}

game_state_t to_msg(const GameInfo& game, int64_t utime, bool finished) {
  game_state_t msg;
  msg.utime = utime;
  msg.state = static_cast<int8_t>(finished ? GameState::kFinished : game.state);
  msg.first_half = game.first_half ? 1 : 0;
  write_game_fields(game, msg);
  return msg;
}

match_event_t to_msg(const sim::MatchEvent& event) {
  match_event_t msg;
  msg.utime = event.utime;
  msg.kind = static_cast<int8_t>(event.kind);
  msg.team = static_cast<int8_t>(event.team);
  const bool about_a_robot = event.kind == sim::MatchEvent::Kind::kPenalty ||
                             event.kind == sim::MatchEvent::Kind::kReleased ||
                             event.kind == sim::MatchEvent::Kind::kFall;
  msg.player = about_a_robot ? static_cast<int8_t>(event.robot.player) : int8_t{0};
  msg.text = event.text;
  return msg;
}

} // namespace touchline::transport
