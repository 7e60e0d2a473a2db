#pragma once
// LookForBall: the head skill of every behaviour. TrackBall while the ball was seen
// recently, HeadScan once it has been lost for more than BALL_LOST_FRAMES. The port of
// behaviour_py/skills/look_for_ball.py.
#include "touchline/behaviour/skills/head_scan.hpp"
#include "touchline/behaviour/skills/track_ball.hpp"

namespace touchline::behaviour::skills {

class LookForBall : public api::Behaviour {
 public:
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

 private:
  TrackBall trackBall_;
  HeadScan headScan_;
};

} // namespace touchline::behaviour::skills
