"""What the skills ask about the ball: seen recently, and where to stand behind it."""
import math

BALL_LOST_FRAMES = 30        # frames (1 s) without the ball before it counts as lost
OPPONENT_GOAL_X = 3000.0     # mm: the opponent goal's centre on a 6000 mm field
OPPONENT_GOAL_Y = 0.0        # mm
BEHIND_BALL_DIST = 200.0     # mm: robot centre to ball centre when lined up behind it
MIN_GOAL_DIST = 1.0          # mm: closer to the goal than this, aim along +x


def ballRecentlySeen(blackboard):
    return blackboard.localisation.ballLostCount <= BALL_LOST_FRAMES


def pointBehindBall(ball, goalX, goalY, behind):
    """(x, y, theta): `behind` mm from `ball` on the line from the goal through the ball,
    facing the goal."""
    dx = goalX - ball.x
    dy = goalY - ball.y
    dist = math.sqrt(dx * dx + dy * dy)  # not hypot: the C++ port's double version gets the same bits
    if dist < MIN_GOAL_DIST:
        dirX, dirY = 1.0, 0.0
    else:
        dirX, dirY = dx / dist, dy / dist
    return ball.x - behind * dirX, ball.y - behind * dirY, math.atan2(dirY, dirX)
