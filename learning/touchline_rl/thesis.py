"""Thesis chapter 3's experiment: walk to (1000, 1000) in a 1 m x 1 m area of the field.

The area is field x, y in [0, 1000] with the target its corner, or centred on the target
(AREAS). The env steps one camera frame of the real walk (GoToPoseEnv) with the thesis's 9
actions; the learner decides once per walk step (HOLD_FRAMES frames). Reward -1 per frame; reaching the target (within
50 mm, and for a heading target within HEADING_TOLERANCE_RAD) ends the episode; leaving the
area ends it with reward -max_steps, so leaving is never cheaper than reaching; an episode
is cut (truncated, bootstrapped) after max_steps frames. Starts are uniform in the area with
a uniform heading. Q starts at 0: optimistic, as every return is negative, and the only
exploration besides epsilon-greedy.

Methods (the issue's three):
  plain       one-step Q-learning over 10 mm cells x 8 headings, target x, y
  traces      Algorithm 3.1 over the same cells, alpha 0.3, no discount, target x, y
  case-based  uniform cases every CASE_SPACING_MM in x, y and every 45 deg of heading,
              Algorithm 3.1's trace, alpha 0.1, no discount, target x, y and heading 0
"""
import math
from dataclasses import dataclass

import numpy as np

from touchline_rl.cases import UniformCases
from touchline_rl.envs import GoToPoseEnv
from touchline_rl.ideal_walk import ideal_walk_env
from touchline_rl.tabular import CaseBasedTraceQLearner, QLearner, TraceQLearner

HEADINGS = 8  # the thesis's 0, pi/4, ..., 7pi/4
SUCCESS_DISTANCE_MM = 50.0
# Case-based target heading tolerance: half the 45 deg spacing of the heading cases, the
# finest heading they are laid out to tell apart. The results also report the 10 deg.
HEADING_TOLERANCE_RAD = math.radians(22.5)
# 100 mm: 11 x 11 x 8 = 968 cases x 9 actions, few enough for optimistic exploration to
# cover (it converged in 30000 episodes on the ideal walk and in the centred area); 50 mm
# (3528 cases) had not begun to reach the target after 4000 episodes on an ideal walk.
CASE_SPACING_MM = 100.0
# Plain Q-learning's alpha and gamma: the thesis gives none. Alpha 0.1, 0.3, 0.5 with
# gamma 1 and 0.99 (--alpha, --gamma; 3000 episodes each) behaved identically, to the frame:
# with Q at 0 every tried action falls below every untried one whatever alpha and gamma,
# so all six were still only exploring. 0.3 as for the traces, and no discount.
PLAIN_ALPHA, PLAIN_GAMMA = 0.3, 1.0
EPSILON = 0.1
# One walk step: the thesis's actions are per step (actions.py), and deciding every frame
# makes a table learn from a state to itself (a 10 mm cell lasts a frame at full speed, a
# 45 deg heading bin 16 frames of turning), which only lowers the chosen action until the
# agent dithers faster than the walk can follow.
HOLD_FRAMES = 8


@dataclass(frozen=True)
class Area:
    """A square of field, lower-left corner (x0, y0), and the target pose in it."""
    x0: float = 0.0
    y0: float = 0.0
    size_mm: float = 1000.0
    cell_mm: float = 10.0
    max_steps: int = 450  # 15 s: about twice the slowest start's shortest walk
    target: tuple = (1000.0, 1000.0, 0.0)

    @property
    def cells(self):
        return int(round(self.size_mm / self.cell_mm))

    @property
    def box(self):
        """((x_min, x_max), (y_min, y_max))."""
        return (self.x0, self.x0 + self.size_mm), (self.y0, self.y0 + self.size_mm)


# The thesis puts the target at (1000, 1000) and says no more of where the area lies.
# corner: field [0, 1000]^2, the target its corner (issue 7's reading, the default);
# centred: field [500, 1500]^2, the target its middle.
AREAS = {"corner": Area(), "centred": Area(x0=500.0, y0=500.0)}


def heading_bin(theta):
    """The nearest of the HEADINGS headings, 0 .. HEADINGS-1."""
    return round(theta / (2 * math.pi / HEADINGS)) % HEADINGS


@dataclass(frozen=True)
class Method:
    name: str
    uses_heading: bool  # the target includes heading 0
    alpha: float
    gamma: float


METHODS = {
    "plain": Method("plain", False, PLAIN_ALPHA, PLAIN_GAMMA),
    "traces": Method("traces", False, 0.3, 1.0),
    "case-based": Method("case-based", True, 0.1, 1.0),
}


def make_env(area, method, heading_tolerance_rad=HEADING_TOLERANCE_RAD, walk="real"):
    """walk: "real" (the simulator's walk) or "ideal" (ideal_walk.py)."""
    (x_min, x_max), (y_min, y_max) = area.box
    kind = {"real": GoToPoseEnv, "ideal": ideal_walk_env}[walk]
    return kind(start_region=area.box, bounds=(x_min, x_max, y_min, y_max),
                success_distance_mm=SUCCESS_DISTANCE_MM,
                success_heading_rad=heading_tolerance_rad if method.uses_heading else None,
                max_steps=area.max_steps, out_of_bounds_reward=-float(area.max_steps))


def make_learner(area, method, seed, alpha=None, gamma=None, epsilon=EPSILON, initial_q=0.0,
                 case_spacing_mm=CASE_SPACING_MM):
    """(learner, encode): encode maps a field pose to the learner's state."""
    alpha = method.alpha if alpha is None else alpha
    gamma = method.gamma if gamma is None else gamma
    if method.name == "case-based":
        count = int(round(area.size_mm / case_spacing_mm)) + 1
        (x_min, x_max), (y_min, y_max) = area.box
        cases = UniformCases((x_min, y_min, 0.0), (x_max, y_max, 2 * math.pi),
                             (count, count, HEADINGS), periodic=(False, False, True))
        learner = CaseBasedTraceQLearner(cases.n_cases, 9, alpha, gamma, epsilon, initial_q, seed=seed)
        return learner, cases.encode
    n, cell, x0, y0 = area.cells, area.cell_mm, area.x0, area.y0

    def encode(pose):
        ix = min(max(int((pose[0] - x0) // cell), 0), n - 1)
        iy = min(max(int((pose[1] - y0) // cell), 0), n - 1)
        return (ix * n + iy) * HEADINGS + heading_bin(pose[2])

    kind = QLearner if method.name == "plain" else TraceQLearner
    return kind(n * n * HEADINGS, 9, alpha, gamma, epsilon, initial_q, seed=seed), encode


def run_episode(env, learner, encode, target, start=None, seed=None, learn=True, hold_frames=None):
    """One episode; returns (frames, outcome): "reached", "left" (the area) or "cut" (after
    max_steps). learn=False runs the greedy policy. Each action is held hold_frames frames
    (HOLD_FRAMES) and learned as one transition with the frames' summed reward; reaching or
    leaving ends it mid-step."""
    hold_frames = hold_frames or HOLD_FRAMES
    options = {"target": target}
    if start is not None:
        options["start"] = start
    _, info = env.reset(seed=seed, options=options)
    state = encode(info["pose"])
    frames = 0
    while True:
        action = learner.act(state, greedy=not learn)
        reward, held = 0.0, 0
        while True:
            _, r, terminated, truncated, info = env.step(action)
            reward += r
            held += 1
            if terminated or truncated or held >= hold_frames:
                break
        next_state = None if terminated else encode(info["pose"])
        frames += held
        if learn:
            learner.learn(state, action, reward, next_state)
        if terminated or truncated:
            break
        state = next_state
    learner.end_episode()
    if not terminated:
        return frames, "cut"
    return frames, "left" if r == env.out_of_bounds_reward else "reached"


def evaluation_starts(area, n, seed=2011):
    """n fixed starts, uniform in the area, none already within the target's radius."""
    rng = np.random.default_rng(seed)
    (x_min, x_max), (y_min, y_max) = area.box
    starts = []
    while len(starts) < n:
        x, y = rng.uniform(x_min, x_max), rng.uniform(y_min, y_max)
        theta = rng.uniform(-math.pi, math.pi)
        if math.hypot(area.target[0] - x, area.target[1] - y) >= SUCCESS_DISTANCE_MM:
            starts.append((float(x), float(y), float(theta)))
    return starts


def evaluate(env, learner, encode, target, starts):
    """The greedy policy from each start: (success rate, [frames to target of successes]).
    Give it an env of its own: its seeded resets would replay a training env's starts."""
    frames = []
    for i, start in enumerate(starts):
        steps, outcome = run_episode(env, learner, encode, target, start=start, seed=i, learn=False)
        if outcome == "reached":
            frames.append(steps)
    return len(frames) / len(starts), frames
