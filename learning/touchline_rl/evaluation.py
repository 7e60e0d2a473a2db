"""Go-to-pose skills on the same fixed seeded starts (issue 7): success (within 50 mm and
10 degrees before the time limit), and the time taken over the lower bound
sqrt((d / Vx)^2 + (dtheta / omega)^2) for the walk's limits."""
import math
import statistics

import numpy as np

from touchline_rl.geometry import field_region, lower_bound_s, reached, relative_target, uniform_pose
from touchline_rl.native import touchline_sim

FRAME_S = 1.0 / 30.0


def fixed_starts(count, field_size, seed=2026):
    """`count` (start, target) pairs uniform over the field inside its lines, headings
    uniform: the same for every skill and every run."""
    rng = np.random.default_rng(seed)
    region = field_region(field_size)
    return [(uniform_pose(rng, region), uniform_pose(rng, region)) for _ in range(count)]


def behaviour_episode(sim, name, params, start, target, seed, distance_mm, heading_rad, max_frames):
    """A C++ behaviour walking from start to target; (frames, reached)."""
    sim.reset(seed, start, behaviour=name, params=params)
    for frame in range(max_frames + 1):
        if reached(relative_target(sim.pose, target), distance_mm, heading_rad):
            return frame, True
        if frame < max_frames:
            sim.step_behaviour()
    return max_frames, False


def pose_params(target):
    return {"x": repr(target[0]), "y": repr(target[1]), "theta": repr(target[2])}


def evaluate(run_episode, starts, limits, progress=None):
    """run_episode(index, start, target) -> (frames, reached) for each start. Returns the
    summary and the per-start rows."""
    rows = []
    for index, (start, target) in enumerate(starts):
        frames, ok = run_episode(index, start, target)
        bound = lower_bound_s(start, target, limits)
        rows.append({"start": start, "target": target, "reached": ok, "time_s": frames * FRAME_S,
                     "lower_bound_s": bound, "ratio": frames * FRAME_S / bound if ok and bound > 0 else None})
        if progress:
            progress(1)
    return summarise(rows), rows


def summarise(rows):
    reached_rows = [r for r in rows if r["reached"]]
    # Failures count as infinitely slow, so a skill cannot look fast by failing the hard starts.
    ratios = [r["ratio"] if r["ratio"] is not None else math.inf for r in rows if r["lower_bound_s"] > 0]
    median_ratio = statistics.median(ratios) if ratios else math.nan
    return {
        "starts": len(rows),
        "success_rate": len(reached_rows) / len(rows) if rows else math.nan,
        "median_time_over_bound": median_ratio,
        "median_time_s": statistics.median(r["time_s"] for r in reached_rows) if reached_rows else math.nan,
    }


def tile_q_runner(q, sim, distance_mm, heading_rad, max_frames):
    def run(index, start, target):
        return touchline_sim.greedy_episode(q, sim, start, target, distance_mm, heading_rad, max_frames, index)
    return run


def behaviour_runner(sim, name, distance_mm, heading_rad, max_frames, extra_params=None):
    def run(index, start, target):
        params = {**pose_params(target), **(extra_params or {})}
        return behaviour_episode(sim, name, params, start, target, index, distance_mm, heading_rad, max_frames)
    return run
