"""What the skills ask about the ball: seen recently, where to aim it, and where to stand behind it."""
import math

from .field import FIELD_EDGE_SLACK, FIELD_HALF_LENGTH, FIELD_HALF_WIDTH

BALL_LOST_FRAMES = 30        # frames (1 s) without the ball before it counts as lost
OPPONENT_GOAL_X = 3000.0     # mm: the opponent goal's centre on a 6000 mm field
OPPONENT_GOAL_Y = 0.0        # mm
BEHIND_BALL_DIST = 200.0     # mm: robot centre to ball centre when lined up behind it
MIN_GOAL_DIST = 1.0          # mm: closer to the goal than this, aim along +x
GOAL_MOUTH_AIM_DIST = 400.0  # mm: a ball nearer a goal's line than this is aimed ...
GOAL_MOUTH_HALF_WIDTH = 600.0  # mm: ... at the mouth's nearest point within this of its centre ...
GOAL_MOUTH_AIM_DEPTH = 200.0  # mm: ... this far inside the goal


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


def goalMouthAim(ballX, ballY, goalX, goalY):
    """(x, y): the goal point (goalX, goalY) on a goal line, as aimed at from a ball at (ballX,
    ballY): the goal point itself, but within GOAL_MOUTH_AIM_DIST of that line the nearest
    point of the mouth (within GOAL_MOUTH_HALF_WIDTH of the goal point) GOAL_MOUTH_AIM_DEPTH
    inside the goal, moving there in proportion (all of the way at the line), so the aim never
    jumps. A ball in the mouth on the line was aimed at the goal's centre, along the line, and
    the spot behind it was at the post: the striker stood against the post until the referee
    restarted a stuck game. A goal point off the goal lines (a pass) is returned as it is."""
    if abs(goalX) != FIELD_HALF_LENGTH:
        return goalX, goalY
    share = min(1.0, max(0.0, 1.0 - abs(goalX - ballX) / GOAL_MOUTH_AIM_DIST))
    if share == 0.0:  # the same bits as before it, far from the line
        return goalX, goalY
    mouthY = min(goalY + GOAL_MOUTH_HALF_WIDTH, max(goalY - GOAL_MOUTH_HALF_WIDTH, ballY))
    return goalX + math.copysign(GOAL_MOUTH_AIM_DEPTH * share, goalX), goalY + (mouthY - goalY) * share


def kickAim(ballX, ballY, goalX, goalY, behind):
    """(x, y): the point to aim the ball at (ballX, ballY) at, for the goal point (goalX,
    goalY). The goal itself (goalMouthAim's point near the goal's line), unless standing
    `behind` mm behind the ball facing it would put the robot more than FIELD_EDGE_SLACK
    beyond a line (no walk takes it there: a ball on a line, where a ball out is put back, had
    strikers standing beside it until someone else moved it). Then the aim turns towards that
    line's direction just enough for the robot to stand FIELD_EDGE_SLACK beyond it, keeping
    its side of the goal: the point is the goal's distance away along the turned aim. The
    touchlines first, then the goal lines. Near a corner no aim keeps the robot within both
    (turning off the goal line put it beyond the touchline again, facing along the goal line
    with the ball beside it, never lining up: 10 s stuck in the own corner): then it aims out
    of the corner, standing equally far beyond both lines (cornerAim)."""
    goalX, goalY = goalMouthAim(ballX, ballY, goalX, goalY)
    dx = goalX - ballX
    dy = goalY - ballY
    dist = math.sqrt(dx * dx + dy * dy)  # as pointBehindBall: the same bits in both ports
    if dist < MIN_GOAL_DIST:
        return goalX, goalY
    dirX, dirY = dx / dist, dy / dist
    turned = False
    limitY = FIELD_HALF_WIDTH + FIELD_EDGE_SLACK
    limitedY = limitAim(dirY, ballY, limitY, behind)
    if limitedY != dirY:
        dirY = limitedY
        dirX = math.copysign(math.sqrt(max(0.0, 1.0 - dirY * dirY)), dirX)
        turned = True
    limitedX = limitAim(dirX, ballX, FIELD_HALF_LENGTH + FIELD_EDGE_SLACK, behind)
    if limitedX != dirX:
        dirX = limitedX
        dirY = math.copysign(math.sqrt(max(0.0, 1.0 - dirX * dirX)), dirY)
        turned = True
        if limitAim(dirY, ballY, limitY, behind) != dirY:  # the touchline again: a corner
            dirX, dirY = cornerAim(ballX, ballY, behind)
    if not turned:
        return goalX, goalY
    return ballX + dist * dirX, ballY + dist * dirY


def cornerAim(ballX, ballY, behind):
    """The unit aim (x, y) out of the corner nearest the ball that stands a robot `behind` mm
    behind the ball equally far beyond both lines' slack: equal room left on both axes
    (roomX - x = roomY - y, the rooms in units of `behind`). Where the room on one axis
    alone allows an aim, this is the one-line aim, so the two meet where a corner starts."""
    roomX = (FIELD_HALF_LENGTH + FIELD_EDGE_SLACK - abs(ballX)) / behind
    roomY = (FIELD_HALF_WIDTH + FIELD_EDGE_SLACK - abs(ballY)) / behind
    c = max(-1.0, min(1.0, roomX - roomY))  # x - y of the aim
    x = (c + math.sqrt(2.0 - c * c)) / 2.0
    return -math.copysign(x, ballX), -math.copysign(x - c, ballY)


def limitAim(component, ball, limit, behind):
    """The aim's `component` along one axis, limited so that standing `behind` mm behind the
    ball (at `ball` on that axis) keeps the robot within +-limit on it."""
    standing = ball - behind * component
    if standing > limit:
        return max(-1.0, min(1.0, (ball - limit) / behind))
    if standing < -limit:
        return max(-1.0, min(1.0, (ball + limit) / behind))
    return component
