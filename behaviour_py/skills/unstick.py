"""Unstick: stuck detection and recovery for a player in PLAYING (issue #17: no robot stuck
more than 10 s). Full matches showed robots turning on the spot for 10 s and more: a search
turn, a target or ball that flips side as localisation jumps, roles swapping between two
targets, a walk that cannot get past a crowd. Reads motion.odometry (what the walk did, free
of localisation's jumps), localisation, gameController and receiver; writes nothing.

  stuck:    since some tick within the last UNSTICK_WINDOW_FRAMES (fewer since play
            resumed), the odometry turned more than UNSTICK_TURN_RAD in all while the net
            move, by odometry or by localisation (the smaller: a walk against a robot steps
            on in odometry only), stayed under UNSTICK_MOVE_MM. Every such stretch counts,
            the shortest too: a fast spin is caught early, and a walk before the turning
            does not hide it (a walk, then 7 s of search turns one way and the other).
  recovery: while stuck, walking without turning (forward and sideways) towards the ball
            (the own if seen recently, else the team ball) or, without either, the field's
            centre; the goalie towards its home. Through Avoid. At least
            UNSTICK_RECOVER_FRAMES ticks, then as long as the window still holds the
            turning without the move: a blocked recovery goes on until the turning is
            older than the window, so no window of play holds more than the limit.
"""
import math

import actioncommand
import robot

from .avoid import Avoid
from .ball import ballRecentlySeen
from .go_to_pose import WALK_GAIN
from .robot_limits import clampWalk
from .search import teamBall

UNSTICK_WINDOW_FRAMES = 300     # frames (10 s, the match statistics' window) of odometry looked back over ...
UNSTICK_TURN_RAD = 3.5          # rad: ... turning more than this in all (they count a full turn as stuck) ...
UNSTICK_MOVE_MM = 300.0         # mm: ... while moving less than this net: stuck
UNSTICK_RECOVER_FRAMES = 60     # frames (2 s): the shortest walk without turning


class Unstick:
    def __init__(self):
        self.odometry = []  # the window's odometry poses and localised positions (x, y, theta, x, y), oldest first
        self.turned = []    # |heading change| (rad) between consecutive poses of the window
        self.recovering = 0  # recovery ticks left
        self.avoid = Avoid()

    def reset(self):
        """Forget the window (outside PLAYING, penalised or fallen: the test counts play only)."""
        self.odometry = []
        self.turned = []
        self.recovering = 0

    def tick(self, blackboard, body, target):
        """body, or while recovering the walk that replaces it; target: the (x, y) field point
        to walk towards (the goalie's home), None for the ball or the field's centre."""
        odometry = blackboard.motion.odometry
        if self.odometry:
            self.turned.append(abs(robot.normaliseTheta(odometry.theta - self.odometry[-1][2])))
        pos = blackboard.localisation.robotPos
        self.odometry.append((odometry.x, odometry.y, odometry.theta, pos.x, pos.y))
        if len(self.odometry) > UNSTICK_WINDOW_FRAMES:
            del self.odometry[0]
            del self.turned[0]
        if self.recovering == 0 and self.stuck():
            self.recovering = UNSTICK_RECOVER_FRAMES
        if self.recovering == 0:
            return body
        self.recovering -= 1
        x, y = self.walkTarget(blackboard, target)
        toTarget = robot.toRobotRelative(blackboard.localisation.robotPos, x, y)
        forward, left = clampWalk(WALK_GAIN * toTarget.x(), WALK_GAIN * toTarget.y())
        return self.avoid.tick(blackboard, actioncommand.walk(forward, left, 0.0), toTarget.distance)

    def stuck(self):
        if sum(self.turned) <= UNSTICK_TURN_RAD - 1e-4:
            return False  # the common case, at C speed (the loop's sum differs in the last bits only)
        (x1, y1, _, u1, v1) = self.odometry[-1]
        turned = 0.0
        for start in range(len(self.turned) - 1, -1, -1):  # back from the newest turn
            turned += self.turned[start]
            if turned <= UNSTICK_TURN_RAD:
                continue
            x0, y0, _, u0, v0 = self.odometry[start]
            if min(math.hypot(x1 - x0, y1 - y0), math.hypot(u1 - u0, v1 - v0)) < UNSTICK_MOVE_MM:
                return True
        return False

    @staticmethod
    def walkTarget(blackboard, target):
        if target is not None:
            return target
        if ballRecentlySeen(blackboard):
            ball = blackboard.localisation.ballPos
            return ball.x, ball.y
        ball = teamBall(blackboard.gameController.playerNumber, blackboard.receiver.messages, blackboard.utime)
        return (0.0, 0.0) if ball is None else ball
