#pragma once
// TrackBall: point the head at the ball, pitched so the ball lies in the visible range; the
// port of behaviour_py/skills/track_ball.py.
#include "touchline/robot_api/behaviour.hpp"

namespace touchline::behaviour::skills {

/// The head request that points the camera at `rr`, pitched so a ball there lies in the
/// visible range.
api::ActionCommand::Head lookAt(const api::RRCoord& rr);

class TrackBall : public api::Behaviour {
 public:
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
};

} // namespace touchline::behaviour::skills
