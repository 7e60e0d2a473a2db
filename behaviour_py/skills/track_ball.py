"""TrackBall: point the head at the ball, pitched so the ball lies in the visible range."""
import actioncommand

from .camera import pitchToSee
from .robot_limits import MAX_HEAD_YAW, clamp


def lookAt(rr):
    """The head request that points the camera at `rr` (robot relative), pitched so a ball
    there lies in the visible range."""
    return actioncommand.head(clamp(rr.heading, -MAX_HEAD_YAW, MAX_HEAD_YAW), pitchToSee(rr.distance))


class TrackBall:
    def tick(self, blackboard):
        # What the camera saw this frame, else localisation's estimate of where it is.
        ball = blackboard.vision.ball if blackboard.vision.ballSeen else blackboard.localisation.ballPosRR
        return actioncommand.compose(head=lookAt(ball))
