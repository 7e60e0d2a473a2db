"""Parallel rollouts of the multi-agent match environment with Ray: each episode one Ray task
(one process of the local or remote cluster), so n episodes take about n / cores times one.

  import ray; ray.init()
  from touchline_rl.rollouts import rollouts, random_policy
  results = rollouts(8, seed=1, policy=random_policy, env_kwargs={"team_size": 2})

Workers import touchline_rl and the touchline_sim extension as the driver does: start Ray with
PYTHONPATH naming learning/ and the extension's folder (bench/env_steps and the tests do).
"""
import numpy as np

from touchline_rl.multi_agent import MatchEnv


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


def rollouts(n, seed, policy, env_kwargs=None):
    """`n` episodes seeded seed, seed + 1, ..., each in its own Ray task (ray.init() first);
    their summaries (see episode()) in seed order."""
    import ray

    task = ray.remote(episode)
    return ray.get([task.remote(seed + i, policy, env_kwargs) for i in range(n)])
