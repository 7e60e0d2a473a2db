"""GoToPoseEnv: walk one robot to a pose, on the in-process simulator (the real walk).

Observation: the target in the robot's frame, float32 (x mm forward, y mm left, heading
error rad in [-pi, pi)). Actions: Discrete over walk commands (default the thesis's nine)
or, continuous, Box([-1, 1]^3) scaled to the walk's limits. One step is one camera frame
(1/30 s). Reward -1 per frame, so the return is minus the frames taken. Terminated on
reaching the pose (within success_distance_mm and success_heading_rad; None ignores the
heading) or on leaving `bounds` (reward out_of_bounds_reward); truncated after max_steps.
"""
import math

import gymnasium as gym
import numpy as np

from touchline_rl.actions import scale_continuous, thesis_actions
from touchline_rl.geometry import field_region, reached, relative_target, uniform_pose
from touchline_rl.native import touchline_sim

# Observation bounds: far beyond any field's diagonal, so every reachable target is inside.
_REACH_MM = 20000.0


class GoToPoseEnv(gym.Env):
    metadata = {"render_modes": []}

    def __init__(self, continuous=False, actions=None, start_region=None, target_region=None, bounds=None,
                 success_distance_mm=50.0, success_heading_rad=math.radians(10.0), max_steps=1200,
                 out_of_bounds_reward=-100.0, world_config="", walk_config=""):
        """start_region, target_region: ((x_min, x_max), (y_min, y_max)) sampled uniformly with a
        uniform heading (default: inside the field's lines); reset(options={"start": pose,
        "target": pose}) fixes either. bounds: (x_min, x_max, y_min, y_max) the robot must stay in."""
        self.sim = touchline_sim.SingleRobotSim(world_config=world_config, walk_config=walk_config)
        self.limits = self.sim.walk_limits
        self.continuous = continuous
        if continuous:
            self.commands = None
            self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(3,), dtype=np.float32)
        else:
            step_s = 0.25  # half the default walk period: the thesis's walk step
            self.commands = tuple(actions) if actions is not None else thesis_actions(step_s)
            self.action_space = gym.spaces.Discrete(len(self.commands))
        self.observation_space = gym.spaces.Box(
            low=np.array([-_REACH_MM, -_REACH_MM, -math.pi], dtype=np.float32),
            high=np.array([_REACH_MM, _REACH_MM, math.pi], dtype=np.float32), dtype=np.float32)
        self.start_region = start_region or field_region(self.sim.field)
        self.target_region = target_region or field_region(self.sim.field)
        self.bounds = bounds
        self.success_distance_mm = success_distance_mm
        self.success_heading_rad = success_heading_rad
        self.max_steps = max_steps
        self.out_of_bounds_reward = out_of_bounds_reward
        self.target = (0.0, 0.0, 0.0)
        self._steps = 0

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        options = options or {}
        start = tuple(options["start"]) if "start" in options else uniform_pose(self.np_random, self.start_region)
        self.target = tuple(options["target"]) if "target" in options else uniform_pose(self.np_random, self.target_region)
        self.sim.reset(int(self.np_random.integers(2**63)), start)
        self._steps = 0
        return self._observation(start), self._info(start)

    def command(self, action):
        """The walk command (forward mm/s, left mm/s, turn rad/s) for `action`."""
        if self.continuous:
            return scale_continuous(action, self.limits)
        return self.commands[int(action)]

    def step(self, action):
        self.sim.step(*self.command(action))
        self._steps += 1
        pose = self.sim.pose
        x, y, heading = relative_target(pose, self.target)
        reward = -1.0
        terminated = reached((x, y, heading), self.success_distance_mm, self.success_heading_rad)
        if not terminated and self.bounds is not None and not self._inside(pose):
            terminated, reward = True, self.out_of_bounds_reward
        truncated = not terminated and self._steps >= self.max_steps
        observation = np.array((x, y, heading), dtype=np.float32)
        return observation, reward, terminated, truncated, self._info(pose)

    def _inside(self, pose):
        x_min, x_max, y_min, y_max = self.bounds
        return x_min <= pose[0] <= x_max and y_min <= pose[1] <= y_max

    def _observation(self, pose):
        return np.array(relative_target(pose, self.target), dtype=np.float32)

    def _info(self, pose):
        return {"pose": pose, "target": self.target, "time_s": self.sim.time_s}
