#include "touchline/learning/observation.hpp"

#include <algorithm>

#include "touchline/learning/pose_message.hpp"

namespace touchline::learning {

namespace {
constexpr double kFrameRateHz = 30.0;

float flag(bool b) { return b ? 1.f : 0.f; }
float capped_age_s(double age_s) { return static_cast<float>(std::clamp(age_s, 0.0, double{kMaxAge_s})); }
} // namespace

int observation_size(int team_size) {
  return kSelfAndGameElements + kTeammateElements * (team_size - 1) + kSeenRobotElements * kSeenRobotSlots;
}

std::vector<std::string> observation_names(int team_size) {
  std::vector<std::string> names{
      "self_x_mm", "self_y_mm", "self_theta_rad", "ball_x_mm", "ball_y_mm", "ball_rel_x_mm", "ball_rel_y_mm",
      "ball_vx_mm_s", "ball_vy_mm_s", "ball_lost_s", "walk_forward_mm_s", "walk_left_mm_s", "walk_turn_rad_s",
      "head_yaw_rad", "standing", "fallen", "kicking", "state_initial", "state_ready", "state_set",
      "state_playing", "state_finished", "state_standby", "penalised", "our_score", "their_score",
      "secs_remaining", "first_half", "our_kickoff", "set_play_ours", "set_play_theirs"};
  for (int slot = 1; slot < team_size; ++slot) {
    const std::string p = "mate" + std::to_string(slot) + "_";
    for (const char* e : {"x_mm", "y_mm", "theta_rad", "age_s", "heard"}) names.push_back(p + e);
  }
  for (int slot = 1; slot <= kSeenRobotSlots; ++slot) {
    const std::string p = "seen" + std::to_string(slot) + "_";
    for (const char* e : {"rel_x_mm", "rel_y_mm", "teammate", "present"}) names.push_back(p + e);
  }
  return names;
}

void observe(const api::Blackboard& bb, int team_size, float* out) {
  const auto& loc = bb.localisation;
  const auto& motion = bb.motion;
  const auto& gc = bb.gameController;
  float* o = out;
  *o++ = loc.robotPos.x;
  *o++ = loc.robotPos.y;
  *o++ = loc.robotPos.theta;
  *o++ = loc.ballPos.x;
  *o++ = loc.ballPos.y;
  *o++ = loc.ballPosRR.x();
  *o++ = loc.ballPosRR.y();
  *o++ = loc.ballVel.x;
  *o++ = loc.ballVel.y;
  *o++ = capped_age_s(loc.ballLostCount / kFrameRateHz);
  *o++ = motion.active.forward;
  *o++ = motion.active.left;
  *o++ = motion.active.turn;
  *o++ = motion.headYaw;
  *o++ = flag(motion.standing);
  *o++ = flag(motion.fallen);
  *o++ = flag(motion.kickPhase != 0);
  for (api::GameState s : {api::GameState::INITIAL, api::GameState::READY, api::GameState::SET,
                           api::GameState::PLAYING, api::GameState::FINISHED, api::GameState::STANDBY})
    *o++ = flag(gc.state == s);
  const int us = gc.team == 1 ? 1 : 0;
  *o++ = flag(gc.penalised);
  *o++ = static_cast<float>(gc.score[static_cast<size_t>(us)]);
  *o++ = static_cast<float>(gc.score[static_cast<size_t>(1 - us)]);
  *o++ = static_cast<float>(gc.secsRemaining);
  *o++ = flag(gc.firstHalf);
  *o++ = flag(gc.kickOffTeam == us);
  const bool set_play = gc.setPlay != api::SetPlay::NONE;
  *o++ = flag(set_play && gc.setPlayTeam == us);
  *o++ = flag(set_play && gc.setPlayTeam == 1 - us);

  for (int player = 1; player <= team_size; ++player) {
    if (player == gc.playerNumber) continue;
    const api::TeamMessage* heard = nullptr;
    for (const auto& m : bb.receiver.messages)
      if (m.playerNumber == player) heard = &m;
    const auto pose = heard ? decode_pose_message(heard->data) : std::nullopt;
    if (pose) {
      *o++ = pose->x;
      *o++ = pose->y;
      *o++ = pose->theta;
      *o++ = capped_age_s(1e-6 * static_cast<double>(bb.utime - heard->utime));
      *o++ = 1.f;
    } else {
      o = std::fill_n(o, 3, 0.f);
      *o++ = kMaxAge_s;
      *o++ = 0.f;
    }
  }

  std::vector<const api::SeenObject*> seen;
  for (const auto& r : bb.vision.robots) seen.push_back(&r);
  std::stable_sort(seen.begin(), seen.end(),
                   [](const api::SeenObject* a, const api::SeenObject* b) { return a->rr.distance < b->rr.distance; });
  for (size_t slot = 0; slot < static_cast<size_t>(kSeenRobotSlots); ++slot) {
    if (slot < seen.size()) {
      *o++ = seen[slot]->rr.x();
      *o++ = seen[slot]->rr.y();
      *o++ = flag(seen[slot]->teammate);
      *o++ = 1.f;
    } else {
      o = std::fill_n(o, kSeenRobotElements, 0.f);
    }
  }
}

} // namespace touchline::learning
