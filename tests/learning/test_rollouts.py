"""Rollouts in Ray tasks: each episode one task, the same summaries as playing them here."""
import os

import pytest

from test_multi_agent import SHORT
from touchline_rl.rollouts import chase_ball_policy, episode, random_policy, rollouts

ray = pytest.importorskip("ray")
KWARGS = {"team_size": 1, "overrides": SHORT}


@pytest.fixture(scope="module")
def local_ray():
    # Workers import touchline_rl and touchline_sim from the driver's environment (PYTHONPATH).
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False,
             runtime_env={"env_vars": {"PYTHONPATH": os.environ.get("PYTHONPATH", "")}})
    yield
    ray.shutdown()


def test_ray_tasks_play_the_episodes_as_this_process_would(local_ray):
    results = rollouts(2, seed=20, policy=random_policy, env_kwargs=KWARGS)
    assert [r["seed"] for r in results] == [20, 21]
    assert results == [episode(20, random_policy, KWARGS), episode(21, random_policy, KWARGS)]
    assert all(r["terminated"] and r["steps"] > 400 for r in results)
    assert results[0]["state_hash"] != results[1]["state_hash"]


def test_an_episode_sums_each_agents_rewards():
    result = episode(3, chase_ball_policy, KWARGS)
    assert set(result["returns"]) == {"team0_p1", "team1_p1"}
    # GoalReward is zero-sum between the teams.
    assert result["returns"]["team0_p1"] == pytest.approx(-result["returns"]["team1_p1"])
