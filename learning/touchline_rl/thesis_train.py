"""Trains one of the thesis's methods (thesis.py) and measures it: a learning curve of the
greedy policy at checkpoints, then the greedy policy from every fixed evaluation start.

Converged (our definition; the thesis judged by watching the agent): the greedy policy
reaches the target from at least CONVERGED_SUCCESS of the curve's starts at each of the
last CONVERGED_HOLD checkpoints, i.e. the curve has reached the threshold and stayed there
within the episode budget.
"""
import math
import statistics
import time

from touchline_rl import thesis

CHECKPOINTS = 20
CURVE_STARTS = 50  # the first 50 evaluation starts: enough to see a trend, cheap to run often
CONVERGED_SUCCESS = 0.9
CONVERGED_HOLD = 3
FRAME_S = 1.0 / 30.0


def converged_at(curve):
    """The episode from which every checkpoint met CONVERGED_SUCCESS, if the last
    CONVERGED_HOLD did; else None."""
    if len(curve) < CONVERGED_HOLD or any(c["greedy_success"] < CONVERGED_SUCCESS for c in curve[-CONVERGED_HOLD:]):
        return None
    first = len(curve)
    while first > 0 and curve[first - 1]["greedy_success"] >= CONVERGED_SUCCESS:
        first -= 1
    return curve[first]["episode"]


def _greedy(env, learner, encode, area, starts):
    rate, frames = thesis.evaluate(env, learner, encode, area.target, starts)
    failures = len(starts) - len(frames)
    mean_frames = (sum(frames) + failures * area.max_steps) / len(starts)  # a failure counts as the cap
    return rate, frames, mean_frames


def train(method_name, episodes, seed, eval_starts, area=thesis.AREAS["corner"], walk="real", progress=None,
          **learner_kwargs):
    """Trains method_name for `episodes` episodes; returns the results as a JSON-able dict.
    progress(n) is called after every n episodes."""
    method = thesis.METHODS[method_name]
    env = thesis.make_env(area, method, walk=walk)
    eval_env = thesis.make_env(area, method, walk=walk)
    learner, encode = thesis.make_learner(area, method, seed, **learner_kwargs)
    env.reset(seed=seed, options={"target": area.target})  # seeds the training starts
    curve_starts = eval_starts[:CURVE_STARTS]
    every = max(1, episodes // CHECKPOINTS)
    curve, window, frames_total, train_s = [], [], 0, 0.0
    for episode in range(1, episodes + 1):
        began = time.perf_counter()
        frames, outcome = thesis.run_episode(env, learner, encode, area.target)
        train_s += time.perf_counter() - began
        frames_total += frames
        window.append((frames, outcome))
        if episode % every == 0 or episode == episodes:
            rate, _, mean_frames = _greedy(eval_env, learner, encode, area, curve_starts)
            curve.append({"episode": episode, "env_steps": frames_total, "greedy_success": rate,
                          "greedy_mean_frames": mean_frames,
                          "train_mean_frames": sum(f for f, _ in window) / len(window),
                          "train_success": sum(o == "reached" for _, o in window) / len(window),
                          "train_left": sum(o == "left" for _, o in window) / len(window)})
            window = []
        if progress:
            progress(1)
    rate, frames, _ = _greedy(eval_env, learner, encode, area, eval_starts)
    result = {"method": method_name, "target": "x, y, heading 0" if method.uses_heading else "x, y",
              "alpha": learner.alpha, "gamma": learner.gamma, "epsilon": learner.epsilon,
              "episodes": episodes, "env_steps": frames_total, "train_wall_s": train_s,
              "converged": converged_at(curve) is not None, "converged_at_episode": converged_at(curve),
              "success_rate": rate, "eval_starts": len(eval_starts),
              "median_time_to_target_s": statistics.median(frames) * FRAME_S if frames else None,
              "curve": curve}
    if method.uses_heading:  # the overall evaluation tolerance, for comparison
        strict = thesis.make_env(area, method, heading_tolerance_rad=math.radians(10.0), walk=walk)
        result["success_rate_heading_10deg"] = thesis.evaluate(strict, learner, encode, area.target, eval_starts)[0]
    return result
