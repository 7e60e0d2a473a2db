"""Blackboards with values for the skill tests.

robot.Blackboard is read-only, and the skills only read attributes, so a tests' board is a
SimpleNamespace with the same attribute names holding real robot.AbsCoord/RRCoord values.
tests/behaviour_cpp/skills/boards.hpp builds the same boards for the C++ port.
"""
import math
from types import SimpleNamespace

import robot


def board(pos=(0.0, 0.0, 0.0), ball=(1000.0, 0.0), seen=True, lost=0, headYaw=0.0, utime=0,
          state=robot.GameState.PLAYING, player=2, penalised=False, fallen=False, messages=()):
    """The robot at pos (x, y, theta), the ball at the field point `ball`; vision and
    localisation agree on it. seen: vision.ballSeen; lost: localisation.ballLostCount;
    state, player, penalised: gameController; fallen: motion.fallen; messages: receiver
    (objects with playerNumber, utime, data)."""
    robotPos = robot.AbsCoord(*pos)
    ballPos = robot.AbsCoord(ball[0], ball[1], 0.0)
    ballRR = robot.toRobotRelative(robotPos, ballPos.x, ballPos.y)
    return SimpleNamespace(
        utime=utime,
        localisation=SimpleNamespace(robotPos=robotPos, ballPos=ballPos, ballPosRR=ballRR, ballLostCount=lost,
                                     robotPosCovariance=[0.0] * 9),
        vision=SimpleNamespace(ballSeen=seen, ball=ballRR),
        motion=SimpleNamespace(headYaw=headYaw, fallen=fallen),
        gameController=SimpleNamespace(state=state, team=0, playerNumber=player, penalised=penalised),
        receiver=SimpleNamespace(messages=list(messages)),
    )


def message(playerNumber, data, utime=0):
    """A received team message, as blackboard.receiver.messages holds them."""
    return SimpleNamespace(playerNumber=playerNumber, utime=utime, data=bytes(data))


def relative(pos, forward, left):
    """The field point `forward`, `left` mm from the robot at pos (x, y, theta)."""
    x, y, theta = pos
    return (x + forward * math.cos(theta) - left * math.sin(theta),
            y + forward * math.sin(theta) + left * math.cos(theta))
