"""GoToPose: walk to a field pose. Thesis Algorithm 4.3 with the forward-first fix.

Far from the target the robot faces it and walks forward (it walks faster forward than
sideways), turning as it walks: the forward speed scales with cos^2 of the target's bearing
(forwardFirstSpeedScale: all of it facing the target, half at 45 degrees, none beyond 90,
where it turns on the spot); within FORWARD_FIRST_DIST, or wherever that is faster (a
target behind a robot that must end facing the other way: a defender falling back, facing
the ball), it runs Algorithm 4.3: turn on the spot while the heading is off by more than
TURN_FIRST_ANGLE, else walk the forward/left decomposition of the target while turning to
the target heading.
Which is faster is estimated from the walk's limits (directTime, forwardFirstTime).
Arrived (with hysteresis): stand, making way for a robot ahead. A target beyond a line (behind
a ball on it) is moved to FIELD_EDGE_SLACK beyond it. Every walk goes through Avoid (avoid.py):
around robots, out of the own goal box, on the field, backing off when blocked.
"""
import math

import actioncommand
import robot

from .avoid import Avoid
from .field import FIELD_EDGE_SLACK, clampToField
from .robot_limits import MAX_FORWARD, MAX_TURN, clampTurn, clampWalk

WALK_GAIN = 2.0                        # 1/s: walk request (mm/s) per mm of position error
TURN_GAIN = 2.0                        # 1/s: turn request (rad/s) per rad of heading error
FORWARD_FIRST_DIST = 400.0             # mm: beyond this, face the target and walk forward
FORWARD_FIRST_LEAVE_DIST = 500.0       # mm: back to forward-first only beyond this
DIRECT_MARGIN_S = 0.25                 # s: Algorithm 4.3 when this much faster (a tie walks forward) ...
DIRECT_HYSTERESIS_S = 0.5              # s: ... and kept until forward-first is this much faster
TURN_FIRST_ANGLE = math.radians(45)    # rad: Algorithm 4.3 turns on the spot beyond this (alone, the ball moved 1 % more of the play than at 15, 16 matches)
ARRIVE_DIST = 40.0                     # mm: arrived within this ...
ARRIVE_ANGLE = 0.1                     # rad: ... and this
LEAVE_DIST = 150.0                     # mm: arrived until pushed beyond this ...
LEAVE_ANGLE = 0.35                     # rad: ... or turned beyond this


def forwardFirstSpeedScale(bearing):
    """The share of its forward speed forward-first walks at with the target `bearing` rad off
    its heading: cos^2, none beyond 90 degrees (turning on the spot first whenever it was off by
    more than 15 degrees, the ball moved 0.9 % less of the play in 16 matches)."""
    facing = math.cos(bearing)
    return facing * facing if facing > 0.0 else 0.0


def directTime(toTarget, turnError):
    """Seconds Algorithm 4.3 needs: turn to the final heading (turnError away), then walk to
    the target in that heading, at the walk's speed in the target's direction."""
    direction = toTarget.heading - turnError  # the target's bearing from the final heading
    forward, left = clampWalk(1e4 * math.cos(direction), 1e4 * math.sin(direction))
    return abs(turnError) / MAX_TURN + toTarget.distance / math.hypot(forward, left)


def forwardFirstTime(toTarget, turnError):
    """Seconds forward-first needs: face the target, walk forward, turn to the final heading."""
    turned = abs(toTarget.heading) + abs(robot.normaliseTheta(turnError - toTarget.heading))
    return turned / MAX_TURN + toTarget.distance / MAX_FORWARD


class GoToPose:
    def __init__(self, x=0.0, y=0.0, theta=0.0, faceBall=False):
        """Target (x, y) in mm and heading theta in rad, field frame; with faceBall the
        robot ends facing the ball instead of theta."""
        self.setTarget(x, y, theta)
        self.faceBall = faceBall
        self.arrived = False
        self.near = False  # running Algorithm 4.3: near, or faster than forward-first
        self.avoid = Avoid()

    def setTarget(self, x, y, theta):
        self.x, self.y = clampToField(x, y, -FIELD_EDGE_SLACK)  # behind a ball on a line, not off the field
        self.theta = theta

    def tick(self, blackboard):
        pos = blackboard.localisation.robotPos
        toTarget = robot.toRobotRelative(pos, self.x, self.y)
        turnError = self.turnError(blackboard, pos)
        self.updateArrived(toTarget.distance, turnError)
        if self.arrived:
            return actioncommand.compose(body=self.avoid.stand(blackboard))
        self.updateNear(toTarget, turnError)
        if not self.near:
            body = self.forwardFirst(toTarget)
        elif abs(turnError) > TURN_FIRST_ANGLE:
            body = actioncommand.walk(turn=clampTurn(TURN_GAIN * turnError))
        else:
            body = self.algorithm43(pos, turnError)
        return actioncommand.compose(body=self.avoid.tick(blackboard, body, toTarget.distance))

    def turnError(self, blackboard, pos):
        """How far (rad, + left) the robot must turn to have its final heading."""
        if self.faceBall:
            ball = blackboard.localisation.ballPos
            return robot.toRobotRelative(pos, ball.x, ball.y).heading
        return robot.normaliseTheta(self.theta - pos.theta)

    def updateArrived(self, distance, turnError):
        if self.arrived:
            self.arrived = distance < LEAVE_DIST and abs(turnError) < LEAVE_ANGLE
        else:
            self.arrived = distance < ARRIVE_DIST and abs(turnError) < ARRIVE_ANGLE

    def updateNear(self, toTarget, turnError):
        direct = directTime(toTarget, turnError)
        forwardFirst = forwardFirstTime(toTarget, turnError)
        if self.near:
            self.near = toTarget.distance < FORWARD_FIRST_LEAVE_DIST or direct < forwardFirst + DIRECT_HYSTERESIS_S
        else:
            self.near = toTarget.distance < FORWARD_FIRST_DIST or direct + DIRECT_MARGIN_S < forwardFirst

    def forwardFirst(self, toTarget):
        """Walk at the target, turning to face it, slower the further it is off the heading."""
        turn = clampTurn(TURN_GAIN * toTarget.heading)
        forward, left = clampWalk(WALK_GAIN * toTarget.distance, 0.0)
        return actioncommand.walk(forward * forwardFirstSpeedScale(toTarget.heading), left, turn)

    def algorithm43(self, pos, turnError):
        """Thesis Algorithm 4.3: the target in the robot frame (runswift angles), walked
        at proportional speed while turning to the final heading."""
        xDiff = self.x - pos.x
        yDiff = self.y - pos.y
        theta = math.pi / 2 - pos.theta
        fwd = xDiff * math.sin(theta) + yDiff * math.cos(theta)
        lft = xDiff * math.cos(theta) - yDiff * math.sin(theta)
        forward, left = clampWalk(WALK_GAIN * fwd, WALK_GAIN * -lft)
        return actioncommand.walk(forward, left, clampTurn(TURN_GAIN * turnError))
