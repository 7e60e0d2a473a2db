"""Avoid: walk around robots instead of into them, never through the own goal box, and back
off when blocked, staying on the field. GoToPose passes every walk it asks for through Avoid.tick.

Reads: motion.sonarLeft/sonarRight/sonarRange_mm, motion.touch* (the foot bumpers and arms),
vision.robots, receiver.messages (the teammates' poses), localisation.robotPos,
gameController.playerNumber, utime. Writes nothing.

Obstacles, robot frame (x forward, y left), from what a robot really has:
- the sonars (thesis Algorithm 2.4): a reading under 1 is a body that far ahead in the left
  or right half of the sonars' corridor, taken SONAR_SIDE_Y off the centre line;
- the robots the camera saw, remembered in the field frame for SEEN_MEMORY_US (the head
  follows the ball, so a robot beside the walk is seen now and then); a sighting replaces
  those remembered within SEEN_MERGE_DIST of it;
- the teammates' own poses from their team messages (fresh, not penalised);
- a touch (a robot against the foot bumpers or an arm, which the camera may never have seen:
  it looks at the ball, and most robots walked into are beside or behind), a body TOUCH_DIST
  away at its sector's middle: TOUCH_FRONT_BEARING either side ahead, beside, behind.

Off a touch: a sensor only tells the sector (TOUCH_FRONT_HALF_WIDTH, TOUCH_SIDE_HALF_WIDTH
either side of its middle), and a robot at its edge is pushed by a walk that passes its
middle. So a walk that closes on any bearing of a touched sector (less than 90 deg from it)
turns, its speed kept, to the nearest direction that closes on none; it stops if every
direction does. This comes after the steering and the backing off, before the own goal box
and the field; a walk that those turn back onto a touched sector stops (a defender beside
its box, sidestepping towards it with an opponent ahead, was sent round the box's front
into the opponent: half the Python supporters' pushing fouls).

Around robots (a tangent rule): the nearest obstacle ahead on the walk's line, within
AVOID_LOOKAHEAD and nearer than the target, and less than AVOID_CLEARANCE off the line,
turns the walk's direction onto the tangent of the AVOID_CLEARANCE circle around it, on the
side the line already passes it (right when dead ahead, so two robots meeting both keep
right). The speed is kept; the turn is not touched.

The own goal box (every player but the goalie): a walk that would bring the robot into the
box grown by BOX_AVOID_MARGIN within BOX_LOOKAHEAD loses its part into the box: the robot
slides along it (beside the box, that part becomes a step towards the field, so a walk
across the box goes round its front). A robot already in it walks as asked (its target
takes it out).

The field (every player): a walk that within FIELD_LOOKAHEAD would take the body centre more
than FIELD_EDGE_SLACK beyond a line loses its part further out over that line; it may still
walk along the line or back in. The referee penalises a robot 200 mm beyond a line (leaving
the field, 45 s out): walks to a stale ball on the touchline, round a crowd or backing off
took four strikers out 12-14 times a match.

Make way: a robot standing at its target steps back from an obstacle ahead of it nearer
than YIELD_DIST (sonar, this frame's sightings, teammates) at YIELD_SPEED (a robot facing
another at contact counts as pushing it).

Back off: a walk that for BLOCKED_FRAMES frames in a row has an obstacle within
BLOCKED_OBSTACLE_DIST in the way and gets less than BLOCKED_PROGRESS closer to its target
becomes BACK_OFF_FRAMES frames of stepping back and aside, away from that obstacle. Frames
count while the walk is asked for every frame (utime at most FRAME_GAP_US apart). Backing off
and making way are steered round the obstacles too, so neither steps into a robot behind.
"""
import math

import actioncommand
import robot

from .field import FIELD_EDGE_SLACK, FIELD_HALF_LENGTH, FIELD_HALF_WIDTH, OWN_BOX_FRONT_X, OWN_BOX_HALF_WIDTH
from .robot_limits import clampWalk
from .team_comm import GOALIE_PLAYER, MESSAGE_STALE_US, decodeMessage

SONAR_SIDE_Y = 50.0              # mm: a sonar's obstacle this far off the centre line
AVOID_LOOKAHEAD = 800.0          # mm: obstacles farther along the walk are left alone
AVOID_CLEARANCE = 400.0          # mm: pass obstacle centres this far (bodies touch at 300)
MIN_WALK_SPEED = 1.0             # mm/s: slower walks are not steered
BOX_AVOID_MARGIN = 100.0         # mm: the own goal box grown by this ...
BOX_LOOKAHEAD = 300.0            # mm: ... is not entered within this along the walk
FIELD_LOOKAHEAD = 150.0          # mm: no walk takes the body centre FIELD_EDGE_SLACK beyond a line within this
BLOCKED_OBSTACLE_DIST = 450.0    # mm: an obstacle this near and in the way can block
BLOCKED_FRAMES = 45              # frames (1.5 s) without progress before backing off
BLOCKED_PROGRESS = 100.0         # mm: nearer to the target than this is progress
BACK_OFF_FRAMES = 30             # frames (1 s) of backing off ...
BACK_OFF_FORWARD = -150.0        # mm/s: ... stepping back ...
BACK_OFF_LEFT = 150.0            # mm/s: ... and aside, away from the obstacle
FRAME_GAP_US = 50000             # us: ticks farther apart start the count again
SEEN_MEMORY_US = 1500000         # us: a robot the camera saw stays an obstacle this long
SEEN_MERGE_DIST = 400.0          # mm: a sighting replaces remembered robots this near it
YIELD_DIST = 400.0               # mm: a standing robot makes way for one ahead this near ...
YIELD_SPEED = 150.0              # mm/s: ... stepping straight away from it
TOUCH_DIST = 200.0               # mm: a robot felt by touch is this far ...
TOUCH_FRONT_BEARING = math.pi / 8  # rad: ... at this bearing either side ahead (a foot bumper's middle)
TOUCH_FRONT_HALF_WIDTH = math.pi / 8  # rad: a foot bumper feels this far either side of its middle
TOUCH_SIDE_HALF_WIDTH = math.pi / 4   # rad: an arm (beside, behind) this far


def touchedSectors(motion):
    """[(middle, half width)], rad, robot frame: the sectors in which a robot touches this one."""
    sectors = ((motion.touchFrontLeft, TOUCH_FRONT_BEARING, TOUCH_FRONT_HALF_WIDTH),
               (motion.touchFrontRight, -TOUCH_FRONT_BEARING, TOUCH_FRONT_HALF_WIDTH),
               (motion.touchLeft, math.pi / 2, TOUCH_SIDE_HALF_WIDTH),
               (motion.touchRight, -math.pi / 2, TOUCH_SIDE_HALF_WIDTH),
               (motion.touchBack, math.pi, TOUCH_SIDE_HALF_WIDTH))
    return [(middle, half) for touched, middle, half in sectors if touched]


def remember(seen, blackboard):
    """seen ([(utime, x, y)], field frame) with this frame's sightings in and the old ones out."""
    utime = blackboard.utime
    pos = blackboard.localisation.robotPos
    cosT = math.cos(pos.theta)
    sinT = math.sin(pos.theta)
    kept = [entry for entry in seen if utime - entry[0] <= SEEN_MEMORY_US]
    for robotSeen in blackboard.vision.robots:
        forward = robotSeen.rr.x()
        left = robotSeen.rr.y()
        x = pos.x + forward * cosT - left * sinT
        y = pos.y + forward * sinT + left * cosT
        kept = [entry for entry in kept if math.hypot(entry[1] - x, entry[2] - y) >= SEEN_MERGE_DIST]
        kept.append((utime, x, y))
    return kept


def obstacles(blackboard, seen=()):
    """[(x, y)]: the obstacles the robot knows of, mm, robot frame; seen: the remembered
    sightings (remember())."""
    found = []
    motion = blackboard.motion
    if motion.sonarLeft < 1.0:
        found.append((motion.sonarLeft * motion.sonarRange_mm, SONAR_SIDE_Y))
    if motion.sonarRight < 1.0:
        found.append((motion.sonarRight * motion.sonarRange_mm, -SONAR_SIDE_Y))
    pos = blackboard.localisation.robotPos
    for _, x, y in seen:
        rr = robot.toRobotRelative(pos, x, y)
        found.append((rr.x(), rr.y()))
    me = blackboard.gameController.playerNumber
    for message in blackboard.receiver.messages:
        if message.playerNumber == me or blackboard.utime - message.utime > MESSAGE_STALE_US:
            continue
        info = decodeMessage(message.data)
        if info is None or info.penalised:
            continue
        rr = robot.toRobotRelative(pos, float(info.robotX), float(info.robotY))
        found.append((rr.x(), rr.y()))
    for middle, _ in touchedSectors(motion):
        found.append((exactZero(TOUCH_DIST * math.cos(middle)), exactZero(TOUCH_DIST * math.sin(middle))))
    return found


def exactZero(value):
    """value, or 0 within 1e-3 of it: cos(pi / 2) is 6e-17 in a double and -4e-8 in a float,
    and a touch beside must be neither ahead nor behind in both ports."""
    return 0.0 if abs(value) < 1e-3 else value


def inOwnBox(x, y):
    """Whether the field point (x, y) is in the own goal box grown by BOX_AVOID_MARGIN."""
    return x < OWN_BOX_FRONT_X + BOX_AVOID_MARGIN and abs(y) < OWN_BOX_HALF_WIDTH + BOX_AVOID_MARGIN


def steer(forward, left, found, targetDist):
    """(forward, left): the walk turned onto the tangent past the nearest obstacle in its way."""
    speed = math.hypot(forward, left)
    if speed < MIN_WALK_SPEED:
        return forward, left
    dirX = forward / speed
    dirY = left / speed
    reach = min(AVOID_LOOKAHEAD, targetDist)
    nearest = None
    for x, y in found:
        along = x * dirX + y * dirY
        across = dirX * y - dirY * x  # + : left of the walk's line
        if along <= 0.0 or along > reach or abs(across) >= AVOID_CLEARANCE:
            continue
        dist = math.hypot(x, y)
        if nearest is None or dist < nearest[0]:
            nearest = (dist, x, y, across)
    if nearest is None:
        return forward, left
    dist, x, y, across = nearest
    side = -1.0 if across >= 0.0 else 1.0  # pass an obstacle on the left on its right
    half = math.pi / 2 if dist <= AVOID_CLEARANCE else math.asin(AVOID_CLEARANCE / dist)
    angle = math.atan2(y, x) + side * half
    return clampWalk(speed * math.cos(angle), speed * math.sin(angle))


def closesOnTouch(sectors, direction):
    """Whether a walk in `direction` (rad, robot frame) closes on a touched sector of
    `sectors` (touchedSectors()): less than 90 deg from some bearing in it."""
    return any(abs(robot.normaliseTheta(direction - middle)) < half + math.pi / 2 - 1e-4 for middle, half in sectors)


def keepOffTouches(motion, forward, left):
    """(forward, left) turned to the nearest direction that closes on no touched sector, its
    speed kept; (0, 0) when every direction closes on one."""
    speed = math.hypot(forward, left)
    sectors = touchedSectors(motion)
    if speed < MIN_WALK_SPEED or not sectors:
        return forward, left

    direction = math.atan2(left, forward)
    if not closesOnTouch(sectors, direction):
        return forward, left
    best = None  # (edge, how far it turns the walk): the first of equal turns (within 1e-4 rad) wins
    for middle, half in sectors:
        for side in (-1.0, 1.0):
            edge = middle + side * (half + math.pi / 2)
            if closesOnTouch(sectors, edge):
                continue
            off = abs(robot.normaliseTheta(edge - direction))
            if best is None or off < best[1] - 1e-4:
                best = (edge, off)
    if best is None:
        return 0.0, 0.0
    return clampWalk(speed * math.cos(best[0]), speed * math.sin(best[0]))


def toFieldAxes(pos, forward, left):
    """The walk (forward, left) of a robot at pos as (vx, vy) along the field's axes."""
    cosT = math.cos(pos.theta)
    sinT = math.sin(pos.theta)
    return forward * cosT - left * sinT, forward * sinT + left * cosT


def toRobotAxes(pos, vx, vy):
    """(vx, vy) along the field's axes as the walk (forward, left) of a robot at pos."""
    cosT = math.cos(pos.theta)
    sinT = math.sin(pos.theta)
    return vx * cosT + vy * sinT, -vx * sinT + vy * cosT


def keepOutOfOwnBox(pos, forward, left):
    """(forward, left) less its part into the own goal box when it would enter it."""
    speed = math.hypot(forward, left)
    if speed < MIN_WALK_SPEED or inOwnBox(pos.x, pos.y):
        return forward, left
    vx, vy = toFieldAxes(pos, forward, left)
    if not inOwnBox(pos.x + vx / speed * BOX_LOOKAHEAD, pos.y + vy / speed * BOX_LOOKAHEAD):
        return forward, left
    if pos.x >= OWN_BOX_FRONT_X + BOX_AVOID_MARGIN:
        vx = max(vx, 0.0)  # in front of the box: no nearer the goal line
    else:
        # beside it: no nearer the centre line; that part goes to the field, round the front
        kept = max(vy, 0.0) if pos.y > 0.0 else min(vy, 0.0)
        vx += abs(vy - kept)
        vy = kept
    return toRobotAxes(pos, vx, vy)


def keepOnField(pos, forward, left):
    """(forward, left) less its part further out over a line when within FIELD_LOOKAHEAD along it
    the body centre would be more than FIELD_EDGE_SLACK beyond that line."""
    speed = math.hypot(forward, left)
    if speed < MIN_WALK_SPEED:
        return forward, left
    vx, vy = toFieldAxes(pos, forward, left)
    aheadX = pos.x + vx / speed * FIELD_LOOKAHEAD
    aheadY = pos.y + vy / speed * FIELD_LOOKAHEAD
    outX = abs(aheadX) > FIELD_HALF_LENGTH + FIELD_EDGE_SLACK and aheadX * vx > 0.0  # further out over a goal line ...
    outY = abs(aheadY) > FIELD_HALF_WIDTH + FIELD_EDGE_SLACK and aheadY * vy > 0.0  # ... or a touchline
    if not outX and not outY:
        return forward, left
    if outX:
        vx = 0.0
    if outY:
        vy = 0.0
    return toRobotAxes(pos, vx, vy)


def keepInBounds(blackboard, forward, left):
    """(forward, left) out of the own goal box (all but the goalie: keepOutOfOwnBox) and on
    the field (keepOnField)."""
    pos = blackboard.localisation.robotPos
    if blackboard.gameController.playerNumber != GOALIE_PLAYER:
        forward, left = keepOutOfOwnBox(pos, forward, left)
    return keepOnField(pos, forward, left)


def keepClear(blackboard, forward, left):
    """(forward, left) off the touched sectors, then keepInBounds: the last word on every walk
    Avoid makes. A walk that the box or a line turns back onto a touched sector becomes (0, 0):
    waiting, not pushing."""
    motion = blackboard.motion
    forward, left = keepInBounds(blackboard, *keepOffTouches(motion, forward, left))
    if math.hypot(forward, left) >= MIN_WALK_SPEED and closesOnTouch(touchedSectors(motion), math.atan2(left, forward)):
        return 0.0, 0.0  # the box or a line turned the walk back into a robot: wait, do not push
    return forward, left


def blocker(found, forward, left):
    """(x, y) of the nearest obstacle within BLOCKED_OBSTACLE_DIST that the walk heads towards, or None."""
    best = None
    for x, y in found:
        dist = math.hypot(x, y)
        if dist < BLOCKED_OBSTACLE_DIST and x * forward + y * left > 0.0 and (best is None or dist < best[0]):
            best = (dist, x, y)
    return None if best is None else (best[1], best[2])


class Avoid:
    def __init__(self):
        self.lastUtime = None
        self.blockedFrames = 0
        self.bestDist = 0.0
        self.backOffFrames = 0
        self.backOffLeft = 0.0
        self.seen = []  # (utime, x, y): robots the camera saw, field frame

    def tick(self, blackboard, body, targetDist):
        """The walk to do for `body` (a walk request) on the way to a target targetDist mm away."""
        utime = blackboard.utime
        if self.lastUtime is None or not 0 < utime - self.lastUtime <= FRAME_GAP_US:
            self.blockedFrames = 0
            self.bestDist = targetDist
            self.backOffFrames = 0
        self.lastUtime = utime
        self.seen = remember(self.seen, blackboard)
        found = obstacles(blackboard, self.seen)
        backing = self.backOffFrames > 0
        if backing:
            self.backOffFrames -= 1
        else:
            backing = self.blocked(found, body.forward, body.left, targetDist)
            if not backing:
                forward, left = steer(body.forward, body.left, found, targetDist)
        if backing:
            forward, left = steer(BACK_OFF_FORWARD, self.backOffLeft, found, AVOID_LOOKAHEAD)
        forward, left = keepClear(blackboard, forward, left)
        return actioncommand.walk(forward, left, 0.0 if backing else body.turn)

    def stand(self, blackboard):
        """Stand, or step away from the nearest obstacle ahead nearer than YIELD_DIST."""
        self.lastUtime = None  # a walk after standing starts its count again
        self.seen = remember(self.seen, blackboard)
        nearest = None
        now = [entry for entry in self.seen if entry[0] == blackboard.utime]  # not remembered ones: they may have gone
        found = obstacles(blackboard, now)
        for x, y in found:
            dist = math.hypot(x, y)
            if x > 0.0 and dist < YIELD_DIST and (nearest is None or dist < nearest[0]):
                nearest = (dist, x, y)
        if nearest is None:
            return actioncommand.stand()
        dist, x, y = nearest
        forward, left = steer(-YIELD_SPEED * x / dist, -YIELD_SPEED * y / dist, found, YIELD_DIST)
        forward, left = keepClear(blackboard, forward, left)
        return actioncommand.walk(forward, left)

    def blocked(self, found, forward, left, targetDist):
        """Whether the walk (forward, left) has been blocked for BLOCKED_FRAMES: then backing
        off starts (this frame is its first)."""
        block = blocker(found, forward, left)
        if block is None or targetDist < self.bestDist - BLOCKED_PROGRESS:
            self.blockedFrames = 0
            self.bestDist = targetDist
            return False
        self.blockedFrames += 1
        if self.blockedFrames < BLOCKED_FRAMES:
            return False
        self.blockedFrames = 0
        self.bestDist = targetDist
        self.backOffFrames = BACK_OFF_FRAMES - 1
        self.backOffLeft = -BACK_OFF_LEFT if block[1] >= 0.0 else BACK_OFF_LEFT
        return True
