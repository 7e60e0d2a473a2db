"""Walk commands as (forward mm/s, left mm/s, turn rad/s), the robot API's units."""
import math

# Thesis section 3.2's nine actions, as printed: forward and left in mm, turn in degrees,
# each per walk step of rUNSWift 2011's walk (our reading: per mm/s they would be too
# slow for its 10 mm cells: 80 mm/s crosses a cell in 4 camera frames; per step of
# T/2 = 0.25 s, 80 mm is 320 mm/s, one cell per frame). The walk clamps them to its
# limits (300 mm/s forward, 200 back, 1.5 rad/s).
THESIS_ACTIONS_PER_STEP = (
    (-80, 0, 0), (-40, 0, 0), (0, 0, 0), (40, 0, 0), (80, 0, 0),
    (0, -40, 0), (0, 40, 0), (0, 0, -30), (0, 0, 30),
)


def thesis_actions(step_s=0.25):
    """The nine actions in API units for a walk step of `step_s` seconds."""
    return tuple((f / step_s, left / step_s, math.radians(t) / step_s) for f, left, t in THESIS_ACTIONS_PER_STEP)


def scale_continuous(action, limits):
    """An action in [-1, 1]^3 as a walk command: forward (back uses the backward limit),
    left and turn as fractions of the walk's limits."""
    forward, left, turn = (min(max(float(a), -1.0), 1.0) for a in action)
    forward *= limits["max_forward_mm_s"] if forward >= 0 else limits["max_backward_mm_s"]
    return forward, left * limits["max_left_mm_s"], turn * limits["max_turn_rad_s"]
