#pragma once
// ActionCommand: what a behaviour requests, shaped like the robot's own. Units: walk
// velocities in mm/s and rad/s, head angles in rad.
#include <cstdint>
#include <vector>

namespace touchline::api::ActionCommand {

enum class ActionType : int8_t {
  NONE = 0,
  STAND = 1,
  WALK = 2,
  DRIBBLE = 3,
  KICK = 4,
  GETUP_FRONT = 5,
  GETUP_BACK = 6,
  DEAD = 7, ///< limp: the robot does nothing (crashed or error)
  GOALIE_DIVE_LEFT = 8,  ///< fall to the left, lie still, stand up where it landed (robot DiveDef)
  GOALIE_DIVE_RIGHT = 9, ///< the same to the right
};

inline const char* name(ActionType type) {
  switch (type) {
    case ActionType::NONE: return "NONE";
    case ActionType::STAND: return "STAND";
    case ActionType::WALK: return "WALK";
    case ActionType::DRIBBLE: return "DRIBBLE";
    case ActionType::KICK: return "KICK";
    case ActionType::GETUP_FRONT: return "GETUP_FRONT";
    case ActionType::GETUP_BACK: return "GETUP_BACK";
    case ActionType::DEAD: return "DEAD";
    case ActionType::GOALIE_DIVE_LEFT: return "GOALIE_DIVE_LEFT";
    case ActionType::GOALIE_DIVE_RIGHT: return "GOALIE_DIVE_RIGHT";
  }
  return "?";
}

struct Head {
  float yaw = 0;          ///< rad, + left
  float pitch = 0;        ///< rad, + down
  bool isRelative = false;///< add to the current angles instead of setting them
  float yawSpeed = 1.0f;  ///< fraction of the maximum head speed, (0, 1]
  float pitchSpeed = 1.0f;///< fraction of the maximum head speed, (0, 1]
};

enum class Foot : int8_t { LEFT = 0, RIGHT = 1 };

struct Body {
  ActionType actionType = ActionType::STAND;
  float forward = 0; ///< mm/s, + forward
  float left = 0;    ///< mm/s, + left
  float turn = 0;    ///< rad/s, + counter-clockwise
  float power = 0;   ///< kick power, [0, 1]
  float bend = 0;    ///< kick direction offset, rad
  float speed = 1;   ///< fraction of the walk's speed limits, (0, 1]
  Foot foot = Foot::LEFT; ///< kicking foot
};

struct LED {
  int32_t chest = 0x00ff00; ///< 0xRRGGBB
};

struct All {
  Head head;
  Body body;
  LED leds;
  float sonar = 0; ///< sonar mode request (unused by the simulator)
  /// Bytes to send to the teammates this frame (empty: none). The league bounds size and
  /// rate (config [comm]); what exceeds them is not sent.
  std::vector<uint8_t> teamMessage;
};

inline Body walk(float forward, float left, float turn) {
  Body b;
  b.actionType = ActionType::WALK;
  b.forward = forward;
  b.left = left;
  b.turn = turn;
  return b;
}

inline Body stand() { return Body{}; }

} // namespace touchline::api::ActionCommand
