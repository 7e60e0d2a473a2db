"""The team evaluation's results file: a sweep's rows in team_results.json's format, with
the goal difference's 95 % interval."""
import json
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import evaluate_teams  # noqa: E402
from sweep_play import COLUMNS  # noqa: E402


def row(seed, goals0, goals1, status="ok"):
    r = {c: "" for c in COLUMNS}
    r.update(cell=0, label="py:Team v cpp:Team", seed=seed, status=status)
    if status == "ok":
        r.update(goals0=goals0, goals1=goals1, goal_difference=goals0 - goals1, falls0=2, falls1=1, sim_s=1300,
                 penalty_kinds=json.dumps({"0:pushing": 2, "1:illegal defender": 1}), possession_frames0=600,
                 possession_frames1=400, stuck_s0=1.5, stuck_s1=0.0, ball_moving_share=0.2 + seed / 10,
                 playing_share=0.6, localisation_worst_mm0=100.0 + seed, localisation_worst_mm1=300.0)
    return r


def test_each_experiment_keeps_its_matches_seed_by_seed_and_gains_the_interval():
    result = evaluate_teams.experiment_result("py:Team", "cpp:Team", [row(2, 0, 1), row(1, 3, 0), row(3, 1, 1)])
    assert result["team0"] == "py:Team" and result["team1"] == "cpp:Team"
    first = result["matches"][0]
    assert first == {"seed": 1, "score": [3, 0], "penalties": {"0:pushing": 2, "1:illegal defender": 1}, "falls": 3,
                     "sim_s": 1300, "possession_frames": [600, 400], "stuck_s": [1.5, 0.0], "ball_moving_share": pytest.approx(0.3),
                     "playing_share": 0.6, "localisation_worst_mm": [101.0, 300.0]}
    assert [m["seed"] for m in result["matches"]] == [1, 2, 3]
    assert result["goal_difference_mean"] == pytest.approx(2 / 3)
    lo, hi = result["goal_difference_ci95"]
    assert lo < 2 / 3 < hi
    assert result["per_match"] == {"pushing": [2, 0], "illegal_defender": [0, 1], "stuck_s_max": [1.5, 0.0],
                                   "ball_moving_share": pytest.approx(0.4),
                                   "ball_moving_share_of_play": pytest.approx(0.4 / 0.6),
                                   "localisation_worst_mm": [102.0, 300.0], "localisation_worst_mm_max": [103.0, 300.0]}


def test_the_experiments_are_cells_of_one_sweep():
    matches = evaluate_teams.matches_of(["ports", "supporters"], 3, ["rules.half_s=300"], ["--duration", "10"])
    assert len(matches) == 6
    assert {(m["cell"], m["team1"]) for m in matches} == {(0, "cpp:Team"), (1, "py:Striker")}
    assert matches[0]["launch"] == ["--set", "rules.half_s=300", "--duration", "10"]


def test_first_seed_moves_every_experiment_to_another_seed_range():
    matches = evaluate_teams.matches_of(["roles_cpp"], 3, [], [], first_seed=41)
    assert [m["seed"] for m in matches] == [41, 42, 43]
    assert {(m["team0"], m["team1"]) for m in matches} == {("cpp:Team", "cpp:Team,supporters=thesis")}


def test_both_sides_counts_pythons_goal_difference_whichever_side_it_played():
    ports = evaluate_teams.experiment_result("py:Team", "cpp:Team", [row(1, 3, 0), row(2, 1, 1)])
    swapped = evaluate_teams.experiment_result("cpp:Team", "py:Team", [row(1, 0, 2), row(2, 2, 1)])
    both = evaluate_teams.both_sides(ports, swapped)
    assert both["matches"] == 4
    assert both["python_minus_cpp_mean"] == pytest.approx((3 + 0 + 2 - 1) / 4)
    lo, hi = both["python_minus_cpp_ci95"]
    assert lo < 1.0 < hi


def test_ports_swapped_plays_the_python_team_as_team_1():
    matches = evaluate_teams.matches_of(["ports", "ports_swapped"], 2, [], [])
    assert {(m["cell"], m["team0"], m["team1"]) for m in matches} == {(0, "py:Team", "cpp:Team"),
                                                                        (1, "cpp:Team", "py:Team")}
