"""Poses as (x mm, y mm, theta rad) tuples, field frame unless named otherwise."""
import math

# The robots' one angle wrap (to [-pi, pi)), the formula the tile indices of a policy use, so
# training and play agree on every heading.
from touchline_rl.robot_skills import wrapAngle as wrap


def relative_target(pose, target):
    """The target as the robot sees it: (x forward, y left, heading error), mm and rad."""
    dx, dy = target[0] - pose[0], target[1] - pose[1]
    c, s = math.cos(pose[2]), math.sin(pose[2])
    return c * dx + s * dy, -s * dx + c * dy, wrap(target[2] - pose[2])


def lower_bound_s(pose, target, limits):
    """The issue's lower bound on the time to a pose: sqrt((d/Vx)^2 + (dtheta/omega)^2)."""
    x, y, heading = relative_target(pose, target)
    return math.hypot(math.hypot(x, y) / limits["max_forward_mm_s"], heading / limits["max_turn_rad_s"])


def reached(relative, distance_mm, heading_rad):
    """Whether a robot-relative target (x, y, heading error) is within distance_mm and, unless
    heading_rad is None, heading_rad."""
    x, y, heading = relative
    if math.hypot(x, y) >= distance_mm:
        return False
    return heading_rad is None or abs(heading) < heading_rad


def field_region(field_size, margin_mm=0.0):
    """((x_min, x_max), (y_min, y_max)): inside the field's lines, less a margin."""
    half_x, half_y = field_size["length_mm"] / 2 - margin_mm, field_size["width_mm"] / 2 - margin_mm
    return (-half_x, half_x), (-half_y, half_y)


def uniform_pose(rng, region):
    """A pose uniform in region ((x_min, x_max), (y_min, y_max)), heading uniform (drawn x, y, heading)."""
    (x0, x1), (y0, y1) = region
    return float(rng.uniform(x0, x1)), float(rng.uniform(y0, y1)), float(rng.uniform(-math.pi, math.pi))
