"""Poses as (x mm, y mm, theta rad) tuples, field frame unless named otherwise."""
import math


def wrap(angle):
    """angle in [-pi, pi)."""
    return (angle + math.pi) % (2 * math.pi) - math.pi


def relative_target(pose, target):
    """The target as the robot sees it: (x forward, y left, heading error), mm and rad."""
    dx, dy = target[0] - pose[0], target[1] - pose[1]
    c, s = math.cos(pose[2]), math.sin(pose[2])
    return c * dx + s * dy, -s * dx + c * dy, wrap(target[2] - pose[2])


def lower_bound_s(pose, target, limits):
    """The issue's lower bound on the time to a pose: sqrt((d/Vx)^2 + (dtheta/omega)^2)."""
    x, y, heading = relative_target(pose, target)
    return math.hypot(math.hypot(x, y) / limits["max_forward_mm_s"], heading / limits["max_turn_rad_s"])
