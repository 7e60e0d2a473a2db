#include "touchline/robot/adapters.hpp"

#include <ctime>

namespace touchline::robot {

void write_game_controller(const SenseFrame& frame, RobotId id, api::Blackboard& blackboard) {
  blackboard.utime = frame.utime;
  auto& gc = blackboard.gameController;
  gc.state = static_cast<api::GameState>(frame.game_state);
  gc.team = id.team;
  gc.playerNumber = id.player;
}

void write_perception(const SenseFrame& frame, const RobotSense& sense, api::Blackboard& blackboard) {
  auto& loc = blackboard.localisation;
  loc.robotPos = {sense.truth.x_mm, sense.truth.y_mm, sense.truth.theta_rad};
  loc.ballPos = {sense.ball_x_mm, sense.ball_y_mm, 0};
  loc.ballPosRR = api::toRobotRelative(loc.robotPos, sense.ball_x_mm, sense.ball_y_mm);
  loc.ballLostCount = 0;
  loc.teamBallPos = loc.ballPos;

  auto& vision = blackboard.vision;
  vision.frame = frame.frame;
  vision.ballSeen = true;
  vision.ball = loc.ballPosRR;
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
