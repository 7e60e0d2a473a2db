"""Rollouts in Ray tasks (learning/rollouts): each match one task, the same summaries as playing
them here; bad arguments are one line."""
import json
import pathlib
import subprocess

import pytest

from test_multi_agent import SHORT
from touchline_rl.rollouts import chase_ball_policy, episode

pytest.importorskip("ray")
ROLLOUTS = pathlib.Path(__file__).resolve().parents[2] / "learning" / "rollouts"
KWARGS = {"team_size": 1, "overrides": SHORT, "max_cycles": None}


def test_ray_tasks_play_the_matches_as_this_process_would(tmp_path):
    out = tmp_path / "rollouts.json"
    command = [str(ROLLOUTS), "--episodes", "2", "--seed", "20", "--team-size", "1", "--workers", "2",
               "--json", str(out)] + [f"--set={s}" for s in SHORT]
    result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    results = json.loads(out.read_text())
    assert [r["seed"] for r in results] == [20, 21]
    for r in results:
        here = episode(r["seed"], chase_ball_policy, KWARGS)
        assert (r["steps"], r["returns"], tuple(r["score"]), r["terminated"], r["state_hash"]) == (
            here["steps"], here["returns"], here["score"], here["terminated"], here["state_hash"])
    assert all(r["terminated"] and r["steps"] > 400 for r in results)
    assert results[0]["state_hash"] != results[1]["state_hash"]
    assert "2 matches" in result.stdout


def test_an_episode_sums_each_agents_rewards():
    result = episode(3, chase_ball_policy, KWARGS)
    assert set(result["returns"]) == {"team0_p1", "team1_p1"}
    # GoalReward is zero-sum between the teams.
    assert result["returns"]["team0_p1"] == pytest.approx(-result["returns"]["team1_p1"])


@pytest.mark.parametrize("args, message", [(["--episodes", "0"], "at least 1"),
                                           (["--set", "rules.half_s=-1"], "rules.half_s")])
def test_bad_arguments_are_one_line_and_exit_2(args, message):
    result = subprocess.run([str(ROLLOUTS), *args], capture_output=True, text=True, timeout=60)
    assert result.returncode == 2 and message in result.stderr
