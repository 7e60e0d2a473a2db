"""TrackBall: point the head at the ball, pitched so the ball lies in the visible range."""
import actioncommand

from .camera import pitchToSee
from .robot_limits import MAX_HEAD_YAW, clamp


class TrackBall:
    def tick(self, blackboard):
        # What the camera saw this frame, else localisation's estimate of where it is.
        if blackboard.vision.ballSeen:
            ball = blackboard.vision.ball
        else:
            ball = blackboard.localisation.ballPosRR
        yaw = clamp(ball.heading, -MAX_HEAD_YAW, MAX_HEAD_YAW)
        return actioncommand.compose(head=actioncommand.head(yaw, pitchToSee(ball.distance)))
