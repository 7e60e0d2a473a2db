"""The supporters (thesis 4.2): Midfielder (Algorithm 4.1) and Defender (Algorithm 4.2).

Both face the ball, never step into the own goal box, keep out of the ball's shooting path
to the opponent goal when in front of it, and walk to their home position once the ball has
been unseen for more than SUPPORTER_BALL_LOST_FRAMES. They walk with GoToPose (Algorithm
4.3 with the forward-first fix).

Algorithm 4.2 keeps the robot's own y; as the thesis text says the defender blocks the path
from the ball to its own goal, its y is the ball-own-goal line's at its target x.
"""
from .ball import OPPONENT_GOAL_X, OPPONENT_GOAL_Y
from .field import OWN_GOAL_X, avoidShootingPath, clampOutOfOwnBox, clampToField
from .go_to_pose import GoToPose

# Algorithm 4.1 (midfielder)
MID_FAR_BALL_X = 2000.0          # mm: ball beyond this: go to the fixed spot ...
MID_FAR_X = 2200.0               # mm: ... (MID_FAR_X, 0)
MID_PARALLEL_BALL_X = 1200.0     # mm: ball beyond this: stand beside it ...
MID_PARALLEL_Y = 1200.0          # mm: ... this far away in y
MID_MAX_DIST_FROM_BALL = 2500.0  # mm: in front of a ball on the own goal line by this much
MID_DIST_SPAN = 4200.0           # mm: ball x from the own goal line to MID_PARALLEL_BALL_X
# Algorithm 4.2 (defender)
DEF_DEEP_BALL_X = -800.0         # mm: ball at or below this: go to the fixed spot ...
DEF_DEEP_X = -1800.0             # mm: ... (DEF_DEEP_X, 0)
DEF_DIST_FROM_BALL = -1250.0     # mm: otherwise this far behind the ball ...
DEF_MAX_X = -1200.0              # mm: ... but never beyond this
# Home positions, walked to when the ball is lost
SUPPORTER_BALL_LOST_FRAMES = 90  # frames (3 s) without the ball before walking home
MID_HOME_X = 0.0                 # mm
MID_HOME_Y = 800.0               # mm
DEF_HOME_X = -1800.0             # mm
DEF_HOME_Y = 0.0                 # mm


def midfielderTarget(ballX, ballY, robotY):
    """Thesis Algorithm 4.1: (x, y) for the ball at (ballX, ballY) and the robot at y robotY."""
    if ballX >= MID_FAR_BALL_X:
        return MID_FAR_X, 0.0
    if ballX >= MID_PARALLEL_BALL_X:
        if robotY < ballY:
            return ballX, ballY - MID_PARALLEL_Y
        return ballX, ballY + MID_PARALLEL_Y
    distFromBall = (MID_PARALLEL_BALL_X - ballX) * MID_MAX_DIST_FROM_BALL / MID_DIST_SPAN
    return ballX + distFromBall, robotY


def defenderTarget(ballX, ballY):
    """Thesis Algorithm 4.2: (x, y) for the ball at (ballX, ballY), y on the ball-own-goal
    line (blocking it)."""
    if ballX <= DEF_DEEP_BALL_X:
        return DEF_DEEP_X, 0.0
    if ballX > -DEF_DIST_FROM_BALL:
        x = DEF_MAX_X
    else:
        x = ballX + DEF_DIST_FROM_BALL
    return x, ballY * (x - OWN_GOAL_X) / (ballX - OWN_GOAL_X)


def supporterTarget(x, y, ballX, ballY, robotY):
    """An algorithm's (x, y) made safe: off the shooting path, out of the own box, on the field."""
    x, y = avoidShootingPath(x, y, ballX, ballY, robotY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y)
    x, y = clampToField(x, y)
    return clampOutOfOwnBox(x, y)


class Supporter:
    """A supporter: target(ballX, ballY, robotY) gives the raw algorithm's position."""
    homeX = 0.0
    homeY = 0.0

    def __init__(self):
        self.goToPose = GoToPose(faceBall=True)
        self.goHome = GoToPose(self.homeX, self.homeY, 0.0)

    def tick(self, blackboard):
        if blackboard.localisation.ballLostCount > SUPPORTER_BALL_LOST_FRAMES:
            return self.goHome.tick(blackboard)
        ball = blackboard.localisation.ballPos
        robotY = blackboard.localisation.robotPos.y
        x, y = self.target(ball.x, ball.y, robotY)
        x, y = supporterTarget(x, y, ball.x, ball.y, robotY)
        self.goToPose.setTarget(x, y, 0.0)
        return self.goToPose.tick(blackboard)

    def target(self, ballX, ballY, robotY):
        raise NotImplementedError


class Midfielder(Supporter):
    homeX = MID_HOME_X
    homeY = MID_HOME_Y

    def target(self, ballX, ballY, robotY):
        return midfielderTarget(ballX, ballY, robotY)


class Defender(Supporter):
    homeX = DEF_HOME_X
    homeY = DEF_HOME_Y

    def target(self, ballX, ballY, robotY):
        return defenderTarget(ballX, ballY)
