#include "touchline/robot/adapters.hpp"

#include <ctime>

namespace touchline::robot {

void write_game_controller(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  blackboard.utime = frame.utime;
  auto& gc = blackboard.gameController;
  gc.state = static_cast<api::GameState>(frame.game.state);
  gc.team = sense.id.team;
  gc.playerNumber = sense.id.player;
  gc.penalised = sense.penalised;
  gc.score = frame.game.score;
  gc.secsRemaining = frame.game.secs_remaining;
}

void write_vision(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  auto& vision = blackboard.vision;
  vision.frame = frame.frame;
  vision.ballSeen = false;
  for (const Observation& o : sense.seen) {
    if (o.kind != ObjectKind::kBall || (vision.ballSeen && o.distance_mm >= vision.ball.distance)) continue;
    vision.ballSeen = true;
    vision.ball = {o.distance_mm, o.heading_rad};
  }
}

void write_fall(const RobotSense& sense, api::Blackboard& blackboard) { blackboard.motion.fallen = sense.fallen; }

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
