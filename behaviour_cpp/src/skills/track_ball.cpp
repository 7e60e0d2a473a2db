#include "touchline/behaviour/skills/track_ball.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/camera.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"

namespace touchline::behaviour::skills {

using namespace api;

ActionCommand::All TrackBall::tick(const Blackboard& blackboard) {
  // What the camera saw this frame, else localisation's estimate of where it is.
  const RRCoord ball = blackboard.vision.ballSeen ? blackboard.vision.ball : blackboard.localisation.ballPosRR;
  const float yaw = clamp(ball.heading, -MAX_HEAD_YAW, MAX_HEAD_YAW);
  return actioncommand::compose(actioncommand::head(yaw, pitchToSee(ball.distance)));
}

} // namespace touchline::behaviour::skills
