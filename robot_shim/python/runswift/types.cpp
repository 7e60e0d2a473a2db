#include "touchline/python/runswift/types.hpp"

namespace touchline::python::runswift {

const char* action_type_name(int type) {
  static const char* const kNames[] = {
      "NONE", "STAND", "WALK", "TURN_DRIBBLE", "GETUP_FRONT", "GETUP_BACK", "TIP_OVER", "KICK", "INITIAL",
      "LIMP", "REF_PICKUP", "GOALIE_SIT", "GOALIE_DIVE_RIGHT", "GOALIE_DIVE_LEFT", "GOALIE_CENTRE",
      "GOALIE_UNCENTRE", "GOALIE_INITIAL", "GOALIE_AFTERSIT_INITIAL", "DEFENDER_CENTRE", "GOALIE_FAST_SIT",
      "MOTION_CALIBRATE", "STAND_STRAIGHT", "LINE_UP", "TEST_ARMS", "RAISE_ARM", "UKEMI_FRONT", "UKEMI_BACK",
      "GOALIE_STAND", "SIT", "SIGNAL_KICK_IN_RIGHT", "SIGNAL_KICK_IN_LEFT", "SIGNAL_GOAL_KICK_RIGHT",
      "SIGNAL_GOAL_KICK_LEFT", "SIGNAL_CORNER_KICK_RIGHT", "SIGNAL_CORNER_KICK_LEFT", "SIGNAL_GOAL_RIGHT",
      "SIGNAL_GOAL_LEFT", "SIGNAL_PUSHING_FREE_KICK_RIGHT", "SIGNAL_PUSHING_FREE_KICK_LEFT", "SIGNAL_FULL_TIME",
      "NUM_ACTION_TYPES"};
  static_assert(sizeof(kNames) / sizeof(kNames[0]) == NUM_ACTION_TYPES + 1, "one name per action type");
  return type >= 0 && type <= NUM_ACTION_TYPES ? kNames[type] : "?";
}

} // namespace touchline::python::runswift
