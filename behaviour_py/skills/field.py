"""The field in the team's own frame (+x towards the opponent goal, own goal at x = -3000,
SPL 2011: 6000 x 4000) and where supporters may stand: out of the own goal box, out of the
ball's shooting path to the opponent goal, on the field.
"""
import math

OWN_GOAL_X = -3000.0             # mm: the own goal line's centre
FIELD_HALF_LENGTH = 3000.0       # mm
FIELD_HALF_WIDTH = 2000.0        # mm
FIELD_MARGIN = 200.0             # mm: supporters' targets stay this far inside the lines
FIELD_EDGE_SLACK = 50.0          # mm: no target or walk takes a robot further beyond a line (the referee penalises 200)
OWN_BOX_FRONT_X = -2400.0        # mm: the own goal box is 600 deep ...
OWN_BOX_HALF_WIDTH = 1100.0      # mm: ... and 2200 wide
BOX_MARGIN = 200.0               # mm: supporters' targets stay this far out of the box
SHOOTING_PATH_CLEARANCE = 500.0  # mm: supporters in front of the ball stay this far off the ball-goal line


def clampToField(x, y, margin=FIELD_MARGIN):
    """(x, y) moved inside the field lines by `margin` (negative: to at most -margin beyond them)."""
    limitX = FIELD_HALF_LENGTH - margin
    limitY = FIELD_HALF_WIDTH - margin
    return min(max(x, -limitX), limitX), min(max(y, -limitY), limitY)


def clampOutOfOwnBox(x, y):
    """(x, y) moved forward out of the own goal box (grown by BOX_MARGIN) if it is in it."""
    frontX = OWN_BOX_FRONT_X + BOX_MARGIN
    if x < frontX and abs(y) < OWN_BOX_HALF_WIDTH + BOX_MARGIN:
        return frontX, y
    return x, y


def avoidShootingPath(x, y, ballX, ballY, robotY, goalX, goalY):
    """(x, y) moved sideways off the line from the ball to (goalX, goalY) when it lies in
    front of the ball within SHOOTING_PATH_CLEARANCE of it; to the side the robot is on."""
    if x <= ballX or goalX <= ballX:
        return x, y
    lineY = ballY + (goalY - ballY) * (x - ballX) / (goalX - ballX)
    if abs(y - lineY) >= SHOOTING_PATH_CLEARANCE:
        return x, y
    if robotY >= lineY:
        return x, lineY + SHOOTING_PATH_CLEARANCE
    return x, lineY - SHOOTING_PATH_CLEARANCE


def distance(x0, y0, x1, y1):
    return math.hypot(x1 - x0, y1 - y0)
