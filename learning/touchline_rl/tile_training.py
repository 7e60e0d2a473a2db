"""Sarsa(lambda) over tile-coded robot-relative targets, trained over the whole field
(the C++ learner in touchline_sim does the stepping; this module picks episodes, reports
progress and evaluates)."""
import math
from dataclasses import dataclass, field

import numpy as np

from touchline_rl.geometry import field_region, lower_bound_s, uniform_pose
from touchline_rl.native import touchline_sim

# The walk commands the learner chooses among (forward mm/s, left mm/s, turn rad/s): the
# walk's limits for travel, turning while walking so it need not stop to steer, and slow
# commands for the last centimetres (the walk accelerates at 600 mm/s^2 and 4 rad/s^2).
ACTIONS = (
    (300, 0, 0), (300, 0, 0.75), (300, 0, -0.75), (150, 0, 1.5), (150, 0, -1.5),
    (0, 0, 1.5), (0, 0, -1.5), (0, 200, 0), (0, -200, 0), (-200, 0, 0),
    (60, 0, 0), (-60, 0, 0), (0, 60, 0), (0, -60, 0), (0, 0, 0.3), (0, 0, -0.3),
)


@dataclass
class TrainingDef:
    episodes: int = 120000             # learning episodes
    seed: int = 1
    alpha: float = 0.2                 # step size, shared by the tilings, decayed linearly ...
    alpha_end: float = 0.05            # ... to this by the last episode (settles the values)
    # Initial Q (frames worse than the lower bound): pessimistic, so the greedy choice
    # follows actions that made progress (the shaping says which) instead of sweeping
    # every untried action in every tile, as optimistic 0 would.
    initial_value: float = -30.0
    lambda_: float = 0.9               # trace decay
    epsilon_start: float = 0.1         # exploration, decayed linearly ...
    epsilon_end: float = 0.01          # ... to this by the last episode
    near_fraction: float = 0.5         # episodes whose target is within near_radius_mm of the start
    near_radius_mm: float = 600.0
    success_distance_mm: float = 50.0
    success_heading_rad: float = math.radians(10.0)
    max_frames: int = 1200             # 40 s
    # Training episodes end sooner: after slack_frames + slack_factor x the lower bound
    # (truncated, so the learner bootstraps), instead of wandering 40 s early on.
    slack_factor: float = 3.0
    slack_frames: int = 60
    coding: dict = field(default_factory=dict)  # TileCodingDef overrides


def make_q(coding_overrides, actions=ACTIONS):
    coding = touchline_sim.TileCodingDef()
    for key, value in coding_overrides.items():
        setattr(coding, key, value)
    return touchline_sim.TileQ(coding, [tuple(map(float, a)) for a in actions])


def field_pose(rng, field_size, margin_mm=0.0):
    """A pose uniform inside the field's lines (less a margin), heading uniform."""
    return uniform_pose(rng, field_region(field_size, margin_mm))


def training_episode(rng, field_size, definition):
    """(start, target): whole field, or a near target for the last centimetres."""
    start = field_pose(rng, field_size)
    if rng.uniform() < definition.near_fraction:
        # near targets stay on the field: draw around a start kept clear of the lines; the
        # distance log-uniform from 10 mm, as many last centimetres as last metres
        start = field_pose(rng, field_size, margin_mm=definition.near_radius_mm)
        r = math.exp(rng.uniform(math.log(10.0), math.log(definition.near_radius_mm)))
        a = rng.uniform(-math.pi, math.pi)
        target = (start[0] + r * math.cos(a), start[1] + r * math.sin(a), float(rng.uniform(-math.pi, math.pi)))
    else:
        target = field_pose(rng, field_size)
    return start, target


def train(definition, q=None, sim=None, progress=None, report_every=1000):
    """Trains (or goes on training) `q`. Yields (episode, mean frames, success rate) every
    report_every episodes; progress(n) is called after each episode."""
    sim = sim or touchline_sim.SingleRobotSim()
    if q is None:
        q = make_q(definition.coding)
        q.weights[:] = definition.initial_value / q.tilings
    learner_def = touchline_sim.SarsaLambdaDef()
    learner_def.alpha, learner_def.lambda_ = definition.alpha, definition.lambda_
    learner = touchline_sim.SarsaLambda(q, learner_def, definition.seed)
    rng = np.random.default_rng(definition.seed)
    frames, successes = [], []
    for episode in range(definition.episodes):
        fraction = episode / max(definition.episodes - 1, 1)
        epsilon = definition.epsilon_start + (definition.epsilon_end - definition.epsilon_start) * fraction
        learner.set_alpha(definition.alpha + (definition.alpha_end - definition.alpha) * fraction)
        start, target = training_episode(rng, sim.field, definition)
        bound_frames = 30 * lower_bound_s(start, target, sim.walk_limits)
        max_frames = min(definition.max_frames, int(definition.slack_frames + definition.slack_factor * bound_frames))
        n, reached = learner.episode(sim, start, target, epsilon, definition.success_distance_mm,
                                     definition.success_heading_rad, max_frames, int(rng.integers(2**63)))
        frames.append(n)
        successes.append(reached)
        if progress:
            progress(1)
        if (episode + 1) % report_every == 0:
            yield episode + 1, float(np.mean(frames)), float(np.mean(successes))
            frames, successes = [], []
