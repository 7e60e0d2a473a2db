#include "touchline/robot/adapters.hpp"

#include <algorithm>
#include <ctime>

namespace touchline::robot {

namespace {

/// A switch, not a cast: the compiler checks that every state is mapped.
api::GameState to_api(GameState state) {
  switch (state) {
    case GameState::kInitial: return api::GameState::INITIAL;
    case GameState::kReady: return api::GameState::READY;
    case GameState::kSet: return api::GameState::SET;
    case GameState::kPlaying: return api::GameState::PLAYING;
    case GameState::kFinished: return api::GameState::FINISHED;
    case GameState::kStandby: return api::GameState::STANDBY;
  }
  return api::GameState::INITIAL;
}

api::SetPlay to_api(SetPlay set_play) {
  switch (set_play) {
    case SetPlay::kNone: return api::SetPlay::NONE;
    case SetPlay::kGoalKick: return api::SetPlay::GOAL_KICK;
    case SetPlay::kPushingFreeKick: return api::SetPlay::PUSHING_FREE_KICK;
    case SetPlay::kCornerKick: return api::SetPlay::CORNER_KICK;
    case SetPlay::kKickIn: return api::SetPlay::KICK_IN;
    case SetPlay::kPenaltyKick: return api::SetPlay::PENALTY_KICK;
  }
  return api::SetPlay::NONE;
}

} // namespace

void write_game_controller(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  blackboard.utime = frame.utime;
  auto& gc = blackboard.gameController;
  gc.state = to_api(frame.game.state);
  gc.team = sense.id.team;
  gc.playerNumber = sense.id.player;
  gc.penalised = sense.penalised;
  gc.score = frame.game.score;
  gc.secsRemaining = frame.game.secs_remaining;
  gc.firstHalf = frame.game.first_half;
  gc.kickOffTeam = frame.game.kickoff_team;
  gc.setPlay = to_api(frame.game.set_play);
  gc.setPlayTeam = frame.game.set_play_team;
  gc.dropInTeam = frame.game.drop_in_team;
  gc.dropInTime = frame.game.drop_in_s;
}

void write_vision(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  auto& vision = blackboard.vision;
  vision.frame = frame.frame;
  vision.ballSeen = false;
  vision.posts.clear();
  vision.robots.clear();
  for (const Observation& o : sense.seen) {
    const api::RRCoord rr{o.distance_mm, o.heading_rad};
    if (o.kind == ObjectKind::kGoalPost) {
      // The world numbers the posts in team 0's frame; team 1's own goal is the world's 2, 3.
      vision.posts.push_back({rr, sense.id.team == 0 ? o.id : (o.id + 2) % 4, false});
    } else if (o.kind == ObjectKind::kTeammate || o.kind == ObjectKind::kOpponent) {
      vision.robots.push_back({rr, o.id, o.kind == ObjectKind::kTeammate});
    }
    if (o.kind != ObjectKind::kBall || (vision.ballSeen && o.distance_mm >= vision.ball.distance)) continue;
    vision.ballSeen = true;
    vision.ball = rr;
  }
}

void write_fall(const RobotSense& sense, api::Blackboard& blackboard) {
  blackboard.motion.fallen = sense.fallen;
  blackboard.motion.sonarLeft = sense.sonar_left;
  blackboard.motion.sonarRight = sense.sonar_right;
  blackboard.motion.touchFrontLeft = sense.touch.front_left;
  blackboard.motion.touchFrontRight = sense.touch.front_right;
  blackboard.motion.touchLeft = sense.touch.left;
  blackboard.motion.touchRight = sense.touch.right;
  blackboard.motion.touchBack = sense.touch.back;
}

void write_receiver(const RobotSense& sense, api::Blackboard& blackboard) {
  auto& messages = blackboard.receiver.messages;
  for (const TeamMessageFrame& arrived : sense.messages) {
    auto it = std::find_if(messages.begin(), messages.end(),
                           [&](const api::TeamMessage& m) { return m.playerNumber == arrived.player; });
    if (it == messages.end()) it = messages.insert(messages.end(), api::TeamMessage{arrived.player, 0, {}});
    if (arrived.sent_utime < it->utime) continue; // an older one overtaken by a newer: keep the newer
    it->utime = arrived.sent_utime;
    it->data = arrived.data;
  }
  std::sort(messages.begin(), messages.end(),
            [](const api::TeamMessage& a, const api::TeamMessage& b) { return a.playerNumber < b.playerNumber; });
}

int64_t thread_cpu_us() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

void BehaviourAdapter::tick(api::Blackboard& blackboard) {
  const int64_t start = clock_();
  blackboard.behaviour.request = behaviour_.tick(blackboard);
  last_cpu_us_ = clock_() - start;
}

} // namespace touchline::robot
