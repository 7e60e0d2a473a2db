"""Blackboards with values for the skill tests.

robot.Blackboard is read-only, and the skills only read attributes, so a tests' board is a
SimpleNamespace with the same attribute names holding real robot.AbsCoord/RRCoord values.
tests/behaviour_cpp/skills/boards.hpp builds the same boards for the C++ port.
"""
import math
from types import SimpleNamespace

import robot

TOUCH_SIDES = ("FrontLeft", "FrontRight", "Left", "Right", "Back")  # motion.touch<side>


def board(pos=(0.0, 0.0, 0.0), ball=(1000.0, 0.0), seen=True, lost=0, headYaw=0.0, utime=0,
          state=robot.GameState.PLAYING, player=2, penalised=False, fallen=False, messages=(), sonar=(1.0, 1.0),
          robots=(), odometry=(0.0, 0.0, 0.0), touch=(), kickOffTeam=0, dropIn=(-1, -1)):
    """The robot at pos (x, y, theta), the ball at the field point `ball`; vision and
    localisation agree on it. seen: vision.ballSeen; lost: localisation.ballLostCount;
    state, player, penalised: gameController; fallen: motion.fallen; messages: receiver
    (objects with playerNumber, utime, data); sonar: motion's (left, right) readings, range
    1000 mm; robots: vision.robots (seenRobot()); odometry: motion.odometry (x, y, theta);
    touch: the touched sectors, of "FrontLeft", "FrontRight", "Left", "Right", "Back"
    (motion.touch*); kickOffTeam: gameController's (this robot's team is 0, as the C++
    Blackboard's defaults have both); dropIn: gameController's (dropInTeam, dropInTime)."""
    robotPos = robot.AbsCoord(*pos)
    ballPos = robot.AbsCoord(ball[0], ball[1], 0.0)
    ballRR = robot.toRobotRelative(robotPos, ballPos.x, ballPos.y)
    return SimpleNamespace(
        utime=utime,
        localisation=SimpleNamespace(robotPos=robotPos, ballPos=ballPos, ballPosRR=ballRR, ballLostCount=lost,
                                     robotPosCovariance=[0.0] * 9),
        vision=SimpleNamespace(ballSeen=seen, ball=ballRR, robots=list(robots)),
        motion=SimpleNamespace(headYaw=headYaw, fallen=fallen, sonarLeft=sonar[0], sonarRight=sonar[1],
                               sonarRange_mm=1000.0, odometry=robot.AbsCoord(*odometry),
                               **{"touch" + side: side in touch for side in TOUCH_SIDES}),
        gameController=SimpleNamespace(state=state, team=0, playerNumber=player, penalised=penalised,
                                       kickOffTeam=kickOffTeam, dropInTeam=dropIn[0], dropInTime=dropIn[1]),
        receiver=SimpleNamespace(messages=list(messages)),
    )


def message(playerNumber, data, utime=0):
    """A received team message, as blackboard.receiver.messages holds them."""
    return SimpleNamespace(playerNumber=playerNumber, utime=utime, data=bytes(data))


def seenRobot(forward, left, number=5, teammate=False):
    """A robot the camera saw `forward`, `left` mm from the robot, as vision.robots holds them."""
    return SimpleNamespace(rr=robot.RRCoord(math.hypot(forward, left), math.atan2(left, forward)), id=number,
                           teammate=teammate)


def relative(pos, forward, left):
    """The field point `forward`, `left` mm from the robot at pos (x, y, theta)."""
    x, y, theta = pos
    return (x + forward * math.cos(theta) - left * math.sin(theta),
            y + forward * math.sin(theta) + left * math.cos(theta))
