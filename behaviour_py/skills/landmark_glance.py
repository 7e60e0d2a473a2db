"""LandmarkGlance: LookForBall, with short glances at a landmark so that localisation keeps
a fix (issue #17 item 3). Following the ball keeps the head low and on the ball, so a robot
may see no landmark for a minute while contacts turn it unseen by its odometry.

Reads localisation.robotPos, robotPosCovariance, ballPosRR, ballLostCount and
motion.headYaw. A glance starts, while the ball is tracked and not hot (seen within
GLANCE_HOT_BALL_DIST), when GLANCE_EVERY_FRAMES have passed since the last one, or
GLANCE_UNSURE_EVERY_FRAMES once the pose's position sigma exceeds GLANCE_SIGMA_MM or its
heading sigma GLANCE_SIGMA_RAD. A hot ball keeps the head unless the pose is lost (position
sigma past GLANCE_LOST_SIGMA_MM): robots toe to toe over a ball hold each other's heads on it
for half a minute while the walk's odometry counts the steps the blocked feet did not take
(2.3 m off in one match of 560). It points the head at the landmark (goal post, field
corner, centre-line end or penalty mark, as the camera reports them) that the estimated
pose places in camera range nearest the ball's bearing, holds it GLANCE_DWELL_FRAMES once
the head is there (GLANCE_MAX_FRAMES at most, short of the ball counting as lost), then
gives the head back to the ball. Frames are counted by its own ticks, never wall time.
"""
import math

import actioncommand
import robot

from .ball import ballRecentlySeen
from .field import FIELD_HALF_LENGTH, FIELD_HALF_WIDTH
from .look_for_ball import LookForBall
from .robot_limits import MAX_HEAD_YAW
from .track_ball import lookAt

GOAL_POST_HALF_SPAN = 700.0         # mm: a goal post from the goal's centre line (SPL 2011)
PENALTY_MARK_X = 1200.0             # mm: penalty marks 1800 mm from the goal lines
GLANCE_EVERY_FRAMES = 150           # frames (5 s) between glances when the pose is sure
GLANCE_UNSURE_EVERY_FRAMES = 45     # frames (1.5 s) between glances when it is not ...
GLANCE_SIGMA_MM = 150.0             # mm: ... its position sigma (x and y together) above this ...
GLANCE_SIGMA_RAD = 0.15             # rad: ... or its heading sigma above this
GLANCE_HOT_BALL_DIST = 600.0        # mm: a ball seen this close keeps the head ...
GLANCE_LOST_SIGMA_MM = 400.0        # mm: ... unless the position sigma (x and y together) is past this
GLANCE_MIN_DIST = 300.0             # mm: landmarks closer than this are no use (bearing)
GLANCE_MAX_DIST = 3500.0            # mm: nor farther than the camera sees looking up, less a margin
GLANCE_ON_TARGET_RAD = 0.1          # rad: the head is on the landmark within this yaw
GLANCE_DWELL_FRAMES = 6             # frames on the landmark (camera misses one in ten)
GLANCE_MAX_FRAMES = 24              # frames a glance lasts at most (the ball is lost after 30)


def landmarks():
    """The landmarks the camera reports, (x, y) in the team frame. The set is symmetric under
    the half turn between the teams' frames, so the same list serves both teams."""
    points = []
    for x in (-FIELD_HALF_LENGTH, FIELD_HALF_LENGTH):
        points += [(x, -GOAL_POST_HALF_SPAN), (x, GOAL_POST_HALF_SPAN), (x, -FIELD_HALF_WIDTH), (x, FIELD_HALF_WIDTH)]
    points += [(0.0, -FIELD_HALF_WIDTH), (0.0, FIELD_HALF_WIDTH), (-PENALTY_MARK_X, 0.0), (PENALTY_MARK_X, 0.0)]
    return points


def glanceTarget(robotPos, ballHeading):
    """The RRCoord of the landmark to glance at from robotPos: in camera range and head reach,
    nearest the ball's bearing `ballHeading` (the quickest there and back); None if none is."""
    best = None
    for x, y in landmarks():
        rr = robot.toRobotRelative(robotPos, x, y)
        if rr.distance < GLANCE_MIN_DIST or rr.distance > GLANCE_MAX_DIST or abs(rr.heading) > MAX_HEAD_YAW:
            continue
        if best is None or abs(rr.heading - ballHeading) < abs(best.heading - ballHeading):
            best = rr
    return best


def positionSigmaPast(localisation, sigmaMm):
    """Whether the pose's position sigma (x and y together) is past sigmaMm."""
    c = localisation.robotPosCovariance
    return c[0] + c[4] > sigmaMm * sigmaMm


def poseUnsure(localisation):
    headingVariance = localisation.robotPosCovariance[8]
    return positionSigmaPast(localisation, GLANCE_SIGMA_MM) or headingVariance > GLANCE_SIGMA_RAD * GLANCE_SIGMA_RAD


def poseLost(localisation):
    return positionSigmaPast(localisation, GLANCE_LOST_SIGMA_MM)


class LandmarkGlance:
    def __init__(self):
        self.lookForBall = LookForBall()
        self.sinceGlance = 0   # frames since the last glance ended
        self.glancing = 0      # frames into the glance under way, 0: none
        self.dwell = 0         # frames the head has been on the landmark

    def tick(self, blackboard):
        loc = blackboard.localisation
        ball = loc.ballPosRR
        hot = (blackboard.vision.ballSeen and blackboard.vision.ball.distance < GLANCE_HOT_BALL_DIST
               and not poseLost(loc))
        if self.glancing:
            target = glanceTarget(loc.robotPos, ball.heading)
            if (target is not None and not hot and self.glancing < GLANCE_MAX_FRAMES
                    and self.dwell < GLANCE_DWELL_FRAMES):
                self.glancing += 1
                return self.aim(blackboard, target)
            self.glancing = 0
            self.sinceGlance = 0
        self.sinceGlance += 1
        every = GLANCE_UNSURE_EVERY_FRAMES if poseUnsure(loc) else GLANCE_EVERY_FRAMES
        if ballRecentlySeen(blackboard) and not hot and self.sinceGlance >= every:
            target = glanceTarget(loc.robotPos, ball.heading)
            if target is not None:
                self.glancing = 1
                self.dwell = 0
                return self.aim(blackboard, target)
        return self.lookForBall.tick(blackboard)

    def aim(self, blackboard, target):
        if abs(blackboard.motion.headYaw - target.heading) < GLANCE_ON_TARGET_RAD:
            self.dwell += 1
        return actioncommand.compose(head=lookAt(target))  # glanceTarget is within the head's yaw
