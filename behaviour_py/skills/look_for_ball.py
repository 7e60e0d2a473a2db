"""LookForBall: the head skill of every behaviour. TrackBall while the ball was seen
recently, HeadScan once it has been lost for more than BALL_LOST_FRAMES."""
from .ball import ballRecentlySeen
from .head_scan import HeadScan
from .track_ball import TrackBall


class LookForBall:
    def __init__(self):
        self.trackBall = TrackBall()
        self.headScan = HeadScan()

    def tick(self, blackboard):
        if ballRecentlySeen(blackboard):
            self.headScan.reset()  # a later search starts from wherever the head is then
            return self.trackBall.tick(blackboard)
        return self.headScan.tick(blackboard)
