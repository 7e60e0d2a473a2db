"""The camera's visible range (thesis 2.2.5) and the head pitch that sees a distance.

maxCameraDist = (elevation - MINPITCH) * 3000 / (MAXPITCH - MINPITCH) + 1000, with MINPITCH
and MAXPITCH the head pitch joint limits. The thesis's pitch grows looking up; the robot's
is + down, so it enters as elevation = MINPITCH + MAXPITCH - pitch: looking up sees
farther. The camera sees 60 degrees across.
"""
from .robot_limits import MAX_HEAD_PITCH, MIN_HEAD_PITCH, clamp

CAMERA_NEAR_RANGE = 1000.0    # mm: visible range at MAX_HEAD_PITCH (fully down)
CAMERA_RANGE_SPAN = 3000.0    # mm: range gained from MAX_HEAD_PITCH to MIN_HEAD_PITCH (fully up)
CAMERA_RANGE_MARGIN = 500.0   # mm: how far past the ball the visible range should reach


def visibleRange(pitch):
    """maxCameraDist at head pitch `pitch` (rad), mm."""
    return (MAX_HEAD_PITCH - pitch) * CAMERA_RANGE_SPAN / (MAX_HEAD_PITCH - MIN_HEAD_PITCH) + CAMERA_NEAR_RANGE


def pitchToSee(distance):
    """The head pitch whose visible range reaches CAMERA_RANGE_MARGIN past `distance` (mm),
    clamped to the joint limits: the thesis formula inverted."""
    wanted = distance + CAMERA_RANGE_MARGIN
    pitch = MAX_HEAD_PITCH - (wanted - CAMERA_NEAR_RANGE) * (MAX_HEAD_PITCH - MIN_HEAD_PITCH) / CAMERA_RANGE_SPAN
    return clamp(pitch, MIN_HEAD_PITCH, MAX_HEAD_PITCH)
