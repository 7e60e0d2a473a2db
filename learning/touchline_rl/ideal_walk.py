"""An ideal walk, to tell what the learners can do from what the real walk lets them do:
the body moves at the commanded velocity, clamped to the walk's limits, from the very
frame it is commanded. No steps, no acceleration, no sway; a stand-in for
SingleRobotSim's step/pose/reset in a GoToPoseEnv (ideal_walk_env)."""
import math

from touchline_rl.envs import GoToPoseEnv
from touchline_rl.geometry import wrap

FRAME_S = 1.0 / 30.0


class IdealWalk:
    def __init__(self, limits):
        self.limits = limits
        self.pose = (0.0, 0.0, 0.0)
        self.time_s = 0.0

    def reset(self, seed, pose):
        del seed  # deterministic
        self.pose = tuple(float(v) for v in pose)
        self.time_s = 0.0

    def step(self, forward, left, turn):
        lim = self.limits
        forward = min(max(forward, -lim["max_backward_mm_s"]), lim["max_forward_mm_s"]) * FRAME_S
        left = min(max(left, -lim["max_left_mm_s"]), lim["max_left_mm_s"]) * FRAME_S
        turn = min(max(turn, -lim["max_turn_rad_s"]), lim["max_turn_rad_s"]) * FRAME_S
        x, y, theta = self.pose
        c, s = math.cos(theta), math.sin(theta)
        self.pose = (x + c * forward - s * left, y + s * forward + c * left, wrap(theta + turn))
        self.time_s += FRAME_S


def ideal_walk_env(**kwargs):
    """A GoToPoseEnv(**kwargs) whose robot walks ideally (same limits as the real walk)."""
    env = GoToPoseEnv(**kwargs)
    env.sim = IdealWalk(env.limits)
    return env
