"""Striker: to the ball, lined up at the opponent goal (LineUpAndKick); carries the ball on
(LineUpAndKick's carry) or kicks, or dribbles while the ball is within STRIKER_DRIBBLE_DIST
of the opponent goal's centre. The choice is made while neither is lining up and kept
through a line-up."""
import math

from .ball import OPPONENT_GOAL_X, OPPONENT_GOAL_Y, ballRecentlySeen
from .line_up_and_kick import LineUpAndKick

STRIKER_DRIBBLE_DIST = 1000.0   # mm: dribble this close to the opponent goal, else kick


def shouldDribble(ballX, ballY):
    return math.hypot(OPPONENT_GOAL_X - ballX, OPPONENT_GOAL_Y - ballY) < STRIKER_DRIBBLE_DIST


class Striker:
    def __init__(self, policy=None):
        """policy: the learned walker's policy file to approach the ball with (None: GoToPose)."""
        self.kick = LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, False, policy=policy, carry=True)
        self.dribble = LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, True, policy=policy)
        self.dribbling = False

    def tick(self, blackboard):
        if ballRecentlySeen(blackboard) and not self.kick.liningUp and not self.dribble.liningUp:
            ball = blackboard.localisation.ballPos
            self.dribbling = shouldDribble(ball.x, ball.y)
        if self.dribbling:
            return self.dribble.tick(blackboard)
        return self.kick.tick(blackboard)
