"""Steps per second of the learning environments on one core (see bench/env_steps): the
single-robot env and, next to it, the multi-agent match env (one step moves every robot)."""
import argparse
import json
import os
import statistics
import time

import gymnasium as gym
import numpy as np

import touchline_rl
from touchline_rl.multi_agent import MatchEnv
from touchline_rl.native import touchline_sim


def steps_per_s(step, reset, steps):
    reset()
    start = time.perf_counter()
    for _ in range(steps):
        if step():
            reset()
    return steps / (time.perf_counter() - start)


def raw_sim(steps):
    sim = touchline_sim.SingleRobotSim()
    return steps_per_s(lambda: sim.step(300.0, 0.0, 0.5), lambda: sim.reset(1, (0.0, 0.0, 0.0)), steps)


def env_runner(env_id, wrapped):
    def run(steps):
        env = gym.make(env_id) if wrapped else gym.make(env_id).unwrapped
        rng = np.random.default_rng(1)
        # Actions drawn beforehand: the figure is the environment's, not the sampler's.
        if isinstance(env.action_space, gym.spaces.Discrete):
            actions = rng.integers(env.action_space.n, size=steps)
        else:
            actions = rng.uniform(-1, 1, size=(steps, 3)).astype(np.float32)
        it = iter(actions)

        def step():
            _, _, terminated, truncated, _ = env.step(next(it))
            return terminated or truncated

        return steps_per_s(step, lambda: env.reset(seed=1), steps)
    return run


def raw_match(team_size):
    def run(steps):
        sim = touchline_sim.MultiRobotSim(overrides=[f"match.team_size={team_size}"])
        actions = np.tile(np.array([300.0, 0.0, 0.5, 0.0, 0.0], dtype=np.float32), (2 * team_size, 1))

        def step():
            sim.step(actions)
            return sim.game_over or sim.out_of_time

        return steps_per_s(step, lambda: sim.reset(1), steps)
    return run


def match_env(team_size):
    def run(steps):
        env = MatchEnv(team_size=team_size)
        rng = np.random.default_rng(1)
        # Actions drawn beforehand, a dict per step as a learner hands them over.
        drawn = rng.uniform(-1, 1, size=(steps, len(env.possible_agents), 5)).astype(np.float32)
        it = iter(drawn)

        def step():
            actions = dict(zip(env.possible_agents, next(it)))
            env.step(actions)
            return not env.agents

        return steps_per_s(step, lambda: env.reset(seed=1), steps)
    return run


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--steps", type=int, default=100_000, help="steps per measurement")
    parser.add_argument("--repeat", type=int, default=3, help="measurements per figure (median reported)")
    parser.add_argument("--json", help="also write the figures here")
    args = parser.parse_args()
    if args.steps < 1 or args.repeat < 1:
        parser.error("--steps and --repeat must be at least 1")
    os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})  # one core
    cases = {
        "touchline_sim.SingleRobotSim.step": raw_sim,
        "GoToPose-v0 (bare env)": env_runner("Touchline/GoToPose-v0", False),
        "GoToPose-v0 (gymnasium.make)": env_runner("Touchline/GoToPose-v0", True),
        "GoToPoseContinuous-v0 (bare env)": env_runner("Touchline/GoToPoseContinuous-v0", False),
        "GoToPoseContinuous-v0 (gymnasium.make)": env_runner("Touchline/GoToPoseContinuous-v0", True),
        "touchline_sim.MultiRobotSim.step (2 v 2)": raw_match(2),
        "MatchEnv ParallelEnv (1 v 1)": match_env(1),
        "MatchEnv ParallelEnv (2 v 2)": match_env(2),
        "MatchEnv ParallelEnv (5 v 5)": match_env(5),
    }
    figures = {}
    for name, run in cases.items():
        figures[name] = statistics.median(run(args.steps) for _ in range(args.repeat))
        print(f"{name:42s} {figures[name]:10.0f} steps/s  ({1e6 / figures[name]:.1f} us/step)")
    if args.json:
        with open(args.json, "w") as out:
            json.dump({"steps": args.steps, "repeat": args.repeat, "steps_per_s": figures}, out, indent=2)


if __name__ == "__main__":
    main()
