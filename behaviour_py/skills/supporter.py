"""The supporters (thesis 4.2): Midfielder (Algorithm 4.1) and Defender (Algorithm 4.2).

Both face the ball, never step into the own goal box, keep out of the ball's shooting path
to the opponent goal when in front of it, and walk to their home position once the ball has
been unseen for more than SUPPORTER_BALL_LOST_FRAMES. They walk with GoToPose (Algorithm
4.3 with the forward-first fix).

Algorithm 4.2 keeps the robot's own y; as the thesis text says the defender blocks the path
from the ball to its own goal, its y is the ball-own-goal line's at its target x.
"""
from dataclasses import dataclass

from .ball import OPPONENT_GOAL_X, OPPONENT_GOAL_Y
from .field import OWN_GOAL_X, avoidShootingPath, clampOutOfOwnBox, clampToField
from .go_to_pose import GoToPose

SUPPORTER_BALL_LOST_FRAMES = 90  # frames (3 s) without the ball before walking home


@dataclass(frozen=True)
class SupporterDef:
    """Where the supporters stand: the numbers of Algorithms 4.1 and 4.2 and the homes (mm,
    team frame). THESIS holds the thesis's own; TUNED (the default) those that played better in
    our matches (the README's "Team results"); the skill parameter supporters=thesis|tuned picks."""
    # Algorithm 4.1 (midfielder)
    midFarBallX: float = 2000.0         # mm: ball beyond this: go to the fixed spot ...
    midFarX: float = 2200.0             # mm: ... (midFarX, 0)
    midParallelBallX: float = 1200.0    # mm: ball beyond this: stand beside it ...
    midParallelY: float = 1200.0        # mm: ... this far away in y
    midMaxDistFromBall: float = 2500.0  # mm: in front of a ball on the own goal line by this much
    # Algorithm 4.2 (defender)
    defDeepBallX: float = -800.0        # mm: ball at or below this: go to the fixed spot ...
    defDeepX: float = -1800.0           # mm: ... (defDeepX, 0)
    defDistFromBall: float = -1250.0    # mm: otherwise this far behind the ball ...
    defMaxX: float = -1200.0            # mm: ... but never beyond this
    # Home positions, walked to when the ball is lost
    midHomeX: float = 0.0               # mm
    midHomeY: float = 800.0             # mm
    defHomeX: float = -1800.0           # mm
    defHomeY: float = 0.0               # mm


THESIS = SupporterDef()
# The defender plays closer behind the ball and up to the -500 line (the thesis: -1200), so it
# meets the clearances in midfield (README "Team results").
TUNED = SupporterDef(defDistFromBall=-900.0, defMaxX=-500.0)
SUPPORTER_DEFS = {"tuned": TUNED, "thesis": THESIS}  # the skill parameter supporters=...; the first the default


def midfielderTarget(ballX, ballY, robotY, supporters):
    """Thesis Algorithm 4.1: (x, y) for the ball at (ballX, ballY) and the robot at y robotY,
    with the numbers of `supporters` (a SupporterDef)."""
    d = supporters
    if ballX >= d.midFarBallX:
        return d.midFarX, 0.0
    if ballX >= d.midParallelBallX:
        if robotY < ballY:
            return ballX, ballY - d.midParallelY
        return ballX, ballY + d.midParallelY
    # The distance grows linearly from 0 (ball at midParallelBallX) to midMaxDistFromBall
    # (ball on the own goal line).
    distFromBall = (d.midParallelBallX - ballX) * d.midMaxDistFromBall / (d.midParallelBallX - OWN_GOAL_X)
    return ballX + distFromBall, robotY


def defenderTarget(ballX, ballY, supporters):
    """Thesis Algorithm 4.2: (x, y) for the ball at (ballX, ballY), y on the ball-own-goal
    line (blocking it), with the numbers of `supporters` (a SupporterDef)."""
    d = supporters
    if ballX <= d.defDeepBallX:
        return d.defDeepX, 0.0
    if ballX > -d.defDistFromBall:
        x = d.defMaxX
    else:
        x = ballX + d.defDistFromBall
    return x, ballY * (x - OWN_GOAL_X) / (ballX - OWN_GOAL_X)


def supporterTarget(x, y, ballX, ballY, robotY):
    """An algorithm's (x, y) made safe: off the shooting path, out of the own box, on the field."""
    x, y = avoidShootingPath(x, y, ballX, ballY, robotY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y)
    x, y = clampToField(x, y)
    return clampOutOfOwnBox(x, y)


class Supporter:
    """A supporter: target(ballX, ballY, robotY) gives the raw algorithm's position;
    supporters: the SupporterDef whose numbers it plays."""

    def __init__(self, supporters=TUNED):
        self.supporters = supporters
        self.goToPose = GoToPose(faceBall=True)
        self.goHome = GoToPose(*self.home(), 0.0)

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

    def home(self):
        raise NotImplementedError


class Midfielder(Supporter):
    def target(self, ballX, ballY, robotY):
        return midfielderTarget(ballX, ballY, robotY, self.supporters)

    def home(self):
        return self.supporters.midHomeX, self.supporters.midHomeY


class Defender(Supporter):
    def target(self, ballX, ballY, robotY):
        return defenderTarget(ballX, ballY, self.supporters)

    def home(self):
        return self.supporters.defHomeX, self.supporters.defHomeY
