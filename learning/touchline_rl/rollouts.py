"""Parallel rollouts of the multi-agent match environment with Ray: each episode one Ray task
(one process of the local or remote cluster), so n episodes take about n / cores times one.

  from touchline_rl.rollouts import rollouts, random_policy
  results = rollouts(8, seed=1, policy=random_policy, env_kwargs={"team_size": 2}, address="local", workers=4)

Workers import touchline_rl and the touchline_sim extension as the driver does: rollouts()
gives a Ray it starts (address "local" or a cluster's) the PYTHONPATH for it (runtime_env());
start your own Ray with it. learning/rollouts plays matches so from the command line.
"""
import argparse
import json
import os
import time
from pathlib import Path

import numpy as np

from touchline_rl.multi_agent import MatchEnv
from touchline_rl.native import touchline_sim


def random_policy(agent, observation, rng):
    """Uniform over the action box."""
    return rng.uniform(-1.0, 1.0, size=5).astype(np.float32)


def chase_ball_policy(agent, observation, rng):
    """A hand-written baseline: turn towards the ball as its own code sees it, walk at it, kick
    when it is at the feet; look towards it. Reads ball_rel_x_mm (5), ball_rel_y_mm (6)."""
    x, y = float(observation[5]), float(observation[6])
    bearing = np.arctan2(y, x)
    near = x * x + y * y < 250.0 ** 2
    return np.array([1.0 if abs(bearing) < 0.5 else 0.0, 0.0, np.clip(bearing, -1, 1), 1.0 if near else -1.0,
                     np.clip(bearing / 2.0, -1, 1)], dtype=np.float32)


def episode(seed, policy, env_kwargs=None):
    """One match from reset(seed) to its end with every agent acting by `policy(agent,
    observation, rng)` (rng: a numpy Generator keyed on the seed). Returns a summary dict:
    seed, steps, returns (per agent), score, terminated (the referee ended the match; else
    truncated), state_hash (the world's at the end)."""
    env = MatchEnv(**(env_kwargs or {}))
    rng = np.random.default_rng(seed)
    observations, _ = env.reset(seed=seed)
    returns = dict.fromkeys(env.possible_agents, 0.0)
    steps, terminated = 0, False
    while env.agents:
        actions = {agent: policy(agent, observations[agent], rng) for agent in env.agents}
        observations, rewards, terminations, _, _ = env.step(actions)
        for agent, reward in rewards.items():
            returns[agent] += reward
        terminated = any(terminations.values())
        steps += 1
    return {"seed": seed, "steps": steps, "returns": returns, "score": env.match_state.score,
            "terminated": terminated, "state_hash": env.state_hash()}


def runtime_env():
    """What a Ray worker needs to import touchline_rl and the touchline_sim extension as this
    process does: PYTHONPATH naming learning/ (or the installed package's folder) and the extension's folder."""
    paths = [str(Path(__file__).resolve().parents[1]), str(Path(touchline_sim.__file__).parent),
             os.environ.get("PYTHONPATH", "")]
    return {"env_vars": {"PYTHONPATH": os.pathsep.join(p for p in paths if p)}}


def rollouts(n, seed, policy, env_kwargs=None, address=None, workers=2):
    """`n` episodes seeded seed, seed + 1, ..., each in its own Ray task; their summaries (see
    episode()) in seed order. address: None, the Ray this process already started (ray.init());
    "local", a Ray instance started here with `workers` CPUs; else a cluster's address (every
    machine needs this tree, built, at the same path), as tools/sweep --ray takes. A Ray
    started here is shut down before returning."""
    import ray

    started = address is not None
    if address == "local":
        ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False, runtime_env=runtime_env())
    elif started:
        ray.init(address=address, log_to_driver=False, runtime_env=runtime_env())
    try:
        task = ray.remote(num_cpus=1, max_retries=0)(episode)
        return ray.get([task.remote(seed + i, policy, env_kwargs) for i in range(n)])
    finally:
        if started:
            ray.shutdown()


POLICIES = {"random": random_policy, "chase_ball": chase_ball_policy}


def main(argv=None):
    parser = argparse.ArgumentParser(description="Multi-agent matches (MatchEnv) in Ray tasks, one a match.")
    parser.add_argument("--episodes", type=int, default=4, help="matches to play (default 4)")
    parser.add_argument("--seed", type=int, default=1, help="the first match's seed; the next ones count up")
    parser.add_argument("--policy", choices=sorted(POLICIES), default="chase_ball", help="every agent's policy")
    parser.add_argument("--team-size", type=int, default=2, help="robots a team (default 2)")
    parser.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                        help="a world config override (repeatable), e.g. rules.half_s=60")
    parser.add_argument("--max-cycles", type=int, help="truncate each match after this many steps")
    parser.add_argument("--ray", default="local", metavar="ADDRESS",
                        help="'local' (default): a Ray instance here; else a cluster's address")
    parser.add_argument("--workers", type=int, default=2, help="CPUs of the local Ray instance (default 2)")
    parser.add_argument("--json", help="also write the summaries here")
    args = parser.parse_args(argv)
    if args.episodes < 1 or args.workers < 1 or args.team_size < 1:
        parser.error("--episodes, --workers and --team-size must be at least 1")
    env_kwargs = {"team_size": args.team_size, "overrides": args.set, "max_cycles": args.max_cycles}
    try:
        MatchEnv(**env_kwargs)  # a bad override: one line here, not a failed task in every worker
    except ValueError as error:
        parser.error(str(error))
    start = time.perf_counter()
    results = rollouts(args.episodes, args.seed, POLICIES[args.policy], env_kwargs, args.ray, args.workers)
    wall_s = time.perf_counter() - start
    for r in results:
        team0 = sum(v for k, v in r["returns"].items() if k.startswith("team0"))
        print(f"seed {r['seed']}: {r['steps']} steps, score {r['score'][0]}-{r['score'][1]}, "
              f"{'ended' if r['terminated'] else 'truncated'}, team 0 return {team0:+.3f}")
    steps = sum(r["steps"] for r in results)
    print(f"{len(results)} matches, {steps} steps in {wall_s:.1f} s ({steps / wall_s:.0f} steps/s with Ray's start)")
    if args.json:
        with open(args.json, "w") as out:
            json.dump(results, out, indent=2)


if __name__ == "__main__":
    main()
