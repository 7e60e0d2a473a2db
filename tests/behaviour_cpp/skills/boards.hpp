#pragma once
// Blackboards with values for the skill tests: the same boards as
// tests/behaviour_py/boards.py builds for the Python skills.
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "touchline/robot_api/blackboard.hpp"

namespace touchline::behaviour::test {

/// The robot at pos, the ball at the field point (ballX, ballY); vision and localisation
/// agree on it. seen: vision.ballSeen; lost: localisation.ballLostCount.
inline api::Blackboard board(api::AbsCoord pos = {}, float ballX = 1000.f, float ballY = 0.f, bool seen = true,
                             int lost = 0, float headYaw = 0.f) {
  api::Blackboard blackboard;
  blackboard.localisation.robotPos = pos;
  blackboard.localisation.ballPos = {ballX, ballY, 0.f};
  blackboard.localisation.ballPosRR = api::toRobotRelative(pos, ballX, ballY);
  blackboard.localisation.ballLostCount = lost;
  blackboard.vision.ballSeen = seen;
  blackboard.vision.ball = blackboard.localisation.ballPosRR;
  blackboard.motion.headYaw = headYaw;
  return blackboard;
}

/// board() in a match, as tests/behaviour_py/boards.py's board() defaults to: state,
/// player, penalised (gameController), fallen (motion), messages (receiver), utime.
inline api::Blackboard teamBoard(api::AbsCoord pos = {}, float ballX = 1000.f, float ballY = 0.f, bool seen = true,
                                 int lost = 0, api::GameState state = api::GameState::PLAYING, int player = 2,
                                 bool penalised = false, bool fallen = false,
                                 std::vector<api::TeamMessage> messages = {}, int64_t utime = 0) {
  api::Blackboard blackboard = board(pos, ballX, ballY, seen, lost);
  blackboard.utime = utime;
  blackboard.gameController.state = state;
  blackboard.gameController.playerNumber = player;
  blackboard.gameController.penalised = penalised;
  blackboard.motion.fallen = fallen;
  blackboard.receiver.messages = std::move(messages);
  return blackboard;
}

/// The field point `forward`, `left` mm from the robot at pos.
inline std::pair<float, float> relative(api::AbsCoord pos, float forward, float left) {
  return {pos.x + forward * std::cos(pos.theta) - left * std::sin(pos.theta),
          pos.y + forward * std::sin(pos.theta) + left * std::cos(pos.theta)};
}

/// A robot the camera saw `forward`, `left` mm from the robot (vision.robots): player
/// `number`, a teammate or not.
inline api::SeenObject seenRobot(float forward, float left, int number = 5, bool teammate = false) {
  return {{std::hypot(forward, left), std::atan2(left, forward)}, number, teammate};
}

inline float radians(float degrees) { return degrees * api::kPi / 180.f; }

} // namespace touchline::behaviour::test
