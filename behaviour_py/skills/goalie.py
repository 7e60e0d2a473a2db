"""Goalie: stays in the own goal box on the line from the goal centre to the ball,
GOALIE_GUARD_DIST out, facing the ball; clears (LineUpAndKick at the opponent goal, carrying
the ball as the striker does) while the ball is in or near the box, the only time it leaves
the box. Lining up a kick instead, with a striker at the ball, held the ball still in the box
with the goalie within 300 mm of it 2.1 % of the play (1.0 % carrying; 16 C++ matches, seeds
1-16); carrying, the ball moved 58.7 -> 60.4 % of the play on seeds 1-16 and 58.4 -> 60.7 % on
17-32, the four strikers scoring 7.9 -> 5.0 and 7.5 -> 4.8 goals a match. Ball lost: back to
(GOALIE_HOME_X, 0) facing the field.
"""
import math

from .ball import OPPONENT_GOAL_X, OPPONENT_GOAL_Y, ballRecentlySeen
from .field import OWN_BOX_FRONT_X, OWN_BOX_HALF_WIDTH, OWN_GOAL_X
from .go_to_pose import GoToPose
from .line_up_and_kick import LineUpAndKick

GOALIE_GUARD_DIST = 400.0    # mm: from the goal centre towards the ball
GOALIE_BOX_MARGIN = 100.0    # mm: the goalie's targets stay this far inside the box
GOALIE_HOME_X = -2700.0      # mm: where it waits while the ball is lost (y 0)
CLEAR_ENTER_MARGIN = 300.0   # mm: clear when the ball is within this of the box ...
CLEAR_LEAVE_MARGIN = 600.0   # mm: ... until it is beyond this


def goalieTarget(ballX, ballY):
    """(x, y) on the goal centre-ball line GOALIE_GUARD_DIST from the goal centre, clamped
    into the box less GOALIE_BOX_MARGIN."""
    dx = ballX - OWN_GOAL_X
    dy = ballY
    dist = math.hypot(dx, dy)
    if dist < 1.0:
        x, y = OWN_GOAL_X + GOALIE_GUARD_DIST, 0.0
    else:
        x, y = OWN_GOAL_X + GOALIE_GUARD_DIST * dx / dist, GOALIE_GUARD_DIST * dy / dist
    minX = OWN_GOAL_X + GOALIE_BOX_MARGIN
    maxX = OWN_BOX_FRONT_X - GOALIE_BOX_MARGIN
    maxY = OWN_BOX_HALF_WIDTH - GOALIE_BOX_MARGIN
    return min(max(x, minX), maxX), min(max(y, -maxY), maxY)


def ballNearBox(ballX, ballY, margin):
    return ballX < OWN_BOX_FRONT_X + margin and abs(ballY) < OWN_BOX_HALF_WIDTH + margin


class Goalie:
    def __init__(self):
        self.goToPose = GoToPose(faceBall=True)
        self.goHome = GoToPose(GOALIE_HOME_X, 0.0, 0.0)
        self.clear = LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, carry=True)
        self.clearing = False

    def tick(self, blackboard):
        if not ballRecentlySeen(blackboard):
            self.clearing = False
            return self.goHome.tick(blackboard)
        ball = blackboard.localisation.ballPos
        if self.clearing:
            self.clearing = ballNearBox(ball.x, ball.y, CLEAR_LEAVE_MARGIN)
        else:
            self.clearing = ballNearBox(ball.x, ball.y, CLEAR_ENTER_MARGIN)
        if self.clearing:
            return self.clear.tick(blackboard)
        x, y = goalieTarget(ball.x, ball.y)
        self.goToPose.setTarget(x, y, 0.0)
        return self.goToPose.tick(blackboard)
