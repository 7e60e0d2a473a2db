#include "touchline/behaviour/skills/track_ball.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/camera.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"

namespace touchline::behaviour::skills {

using namespace api;

ActionCommand::Head lookAt(const RRCoord& rr) {
  return actioncommand::head(clamp(rr.heading, -MAX_HEAD_YAW, MAX_HEAD_YAW), pitchToSee(rr.distance));
}

ActionCommand::All TrackBall::tick(const Blackboard& blackboard) {
  // What the camera saw this frame, else localisation's estimate of where it is.
  return actioncommand::compose(lookAt(blackboard.vision.ballSeen ? blackboard.vision.ball
                                                                  : blackboard.localisation.ballPosRR));
}

} // namespace touchline::behaviour::skills
