#pragma once
// What happened in a match worth telling: the referee's decisions, falls. The world node
// publishes each one (match_event_t on TL_EVENT) and the launcher's summary lists them.
#include <cstdint>
#include <string>

#include "touchline/frame.hpp"

namespace touchline::sim {

struct MatchEvent {
  enum class Kind : int8_t {
    kStateChange = 0, ///< `text` names the new state
    kGoal = 1,        ///< `team` scored
    kPenalty = 2,     ///< `robot` penalised, `text` says why
    kReleased = 3,    ///< `robot` back on the field after its penalty
    kFall = 4,        ///< `robot` fell (pushed)
    kBallOut = 5,     ///< the ball left the field and was put back
    kSetPlay = 6,     ///< a set play began (`team` takes it, `text` names it) or ended (team -1)
    kGameStuck = 7,   ///< the game was stuck; `team` kicks off again, `text` says why
  };
  int64_t utime = 0;
  Kind kind = Kind::kStateChange;
  RobotId robot;  ///< kPenalty, kReleased, kFall
  int team = -1;  ///< kGoal
  std::string text;
};

} // namespace touchline::sim
