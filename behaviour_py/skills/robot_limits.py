"""The robot's walk and head limits, and clamping to them. The one place they live.

Units: mm/s, rad/s, rad. Values match config/walk.ini and the MotionAdapter's HeadDef.
"""

MAX_FORWARD = 300.0     # mm/s, walking forward
MAX_BACKWARD = 200.0    # mm/s, walking backward
MAX_LEFT = 200.0        # mm/s, sideways either way
MAX_TURN = 1.5          # rad/s, either way

MAX_HEAD_YAW = 2.08     # rad, either side
MIN_HEAD_PITCH = -0.67  # rad, looking up (pitch is + down)
MAX_HEAD_PITCH = 0.51   # rad, looking down


def clamp(value, low, high):
    value = low if low > value else value  # min(max(value, low), high), without the calls
    return high if high < value else value


def clampTurn(turn):
    return clamp(turn, -MAX_TURN, MAX_TURN)


def clampWalk(forward, left):
    """Scales (forward, left) down into the walk limits, keeping its direction.

    Clamping each component alone would bend the path: the very error thesis 4.3 warns of.
    """
    scale = 1.0
    maxForward = MAX_FORWARD if forward >= 0.0 else MAX_BACKWARD
    if abs(forward) > maxForward:
        scale = maxForward / abs(forward)
    if abs(left) * scale > MAX_LEFT:
        scale = MAX_LEFT / abs(left)
    return forward * scale, left * scale
