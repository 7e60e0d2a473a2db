"""The tile-coded learner's Python side: policy files the behaviours read, the evaluation
summary, and the train/evaluate commands."""
import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

from skills.tile_policy import loadPolicy
from touchline_rl.evaluation import evaluate, fixed_starts, summarise
from touchline_rl.policy_file import read_policy, write_policy
from touchline_rl.tile_training import ACTIONS, TrainingDef, make_q, train

REPO = pathlib.Path(__file__).resolve().parents[2]
SMALL = {"tilings": 4, "tiles_distance": 5, "tiles_bearing": 6, "tiles_heading": 6}


def random_q(seed=1):
    q = make_q(SMALL)
    q.weights[:] = np.random.default_rng(seed).normal(size=q.weights.size).astype(np.float32)
    return q


def test_a_written_policy_reads_back_exactly(tmp_path):
    q = random_q()
    write_policy(tmp_path / "p.policy", q, 40.0, 0.1, comments=["a test"])
    again, distance, heading = read_policy(tmp_path / "p.policy")
    np.testing.assert_array_equal(np.asarray(again.weights), np.asarray(q.weights))
    np.testing.assert_allclose(again.actions, q.actions)
    assert (distance, heading) == (40.0, 0.1)


def test_the_deployed_python_reader_acts_as_the_learner(tmp_path):
    """behaviour_py's TilePolicy on our file picks the learner's greedy action."""
    q = random_q(2)
    write_policy(tmp_path / "p.policy", q)
    deployed = loadPolicy(str(tmp_path / "p.policy"))
    rng = np.random.default_rng(3)
    for x, y, heading in rng.uniform((-5000, -5000, -4), (5000, 5000, 4), size=(500, 3)):
        assert deployed.greedyAction(x, y, heading) == q.greedy(x, y, heading)


def test_a_bad_policy_file_names_itself(tmp_path):
    path = tmp_path / "bad.policy"
    path.write_text("touchline-policy 1\nfeatures polar-log\n")
    with pytest.raises(ValueError, match="bad.policy"):
        read_policy(path)
    path.write_text("something else\n")
    with pytest.raises(ValueError, match="not a"):
        read_policy(path)


def test_summary_counts_failures_as_infinitely_slow():
    rows = [{"reached": True, "time_s": 2.0, "lower_bound_s": 1.0, "ratio": 2.0},
            {"reached": False, "time_s": 40.0, "lower_bound_s": 1.0, "ratio": None},
            {"reached": False, "time_s": 40.0, "lower_bound_s": 1.0, "ratio": None}]
    summary = summarise(rows)
    assert summary["success_rate"] == pytest.approx(1 / 3)
    assert summary["median_time_over_bound"] == math.inf
    assert summary["median_time_s"] == 2.0


def test_fixed_starts_are_fixed_and_on_the_field():
    field = {"length_mm": 6000.0, "width_mm": 4000.0}
    starts = fixed_starts(50, field)
    assert starts == fixed_starts(50, field)
    for start, target in starts:
        for pose in (start, target):
            assert abs(pose[0]) <= 3000 and abs(pose[1]) <= 2000 and -math.pi <= pose[2] <= math.pi


def test_training_improves_the_greedy_policy_on_near_targets():
    definition = TrainingDef(episodes=600, near_fraction=1.0, near_radius_mm=400.0, coding=SMALL)
    q = make_q(SMALL)
    q.weights[:] = definition.initial_value / q.tilings
    from touchline_rl.native import touchline_sim
    sim = touchline_sim.SingleRobotSim()
    rng = np.random.default_rng(11)
    cases = [((0.0, 0.0, 0.0), (float(r * math.cos(a)), float(r * math.sin(a)), float(h)))
             for r, a, h in rng.uniform((100, -math.pi, -1), (400, math.pi, 1), size=(20, 3))]

    def success():
        run = lambda i, s, t: touchline_sim.greedy_episode(q, sim, s, t, 50.0, math.radians(10), 300, i)  # noqa: E731
        return evaluate(run, cases, sim.walk_limits)[0]["success_rate"]

    before = success()
    for _ in train(definition, q=q, sim=sim, report_every=600):
        pass
    assert success() >= before + 0.3


def run(*args):
    return subprocess.run([str(REPO / "learning" / args[0]), *args[1:]], capture_output=True, text=True)


def test_train_and_evaluate_commands_write_their_files(tmp_path):
    policy = tmp_path / "p.policy"
    trained = run("train_tiles", "--episodes", "20", "--report-every", "10", "--policy", str(policy),
                  "--out", str(tmp_path / "tiles"), "--no-progress")
    assert trained.returncode == 0, trained.stderr
    assert (tmp_path / "tiles" / "curve.png").stat().st_size > 0
    assert (tmp_path / "tiles" / "training.json").exists()
    evaluated = run("evaluate", "--policy", str(policy), "--starts", "3", "--out", str(tmp_path / "eval"),
                    "--no-progress")
    assert evaluated.returncode == 0, evaluated.stderr
    table = (tmp_path / "eval" / "results.md").read_text()
    assert "hand-coded (C++ GoToPose)" in table and "learned, deployed (C++ LearnedGoToPose)" in table


@pytest.mark.parametrize("command, args, message", [
    ("train_tiles", ["--episodes", "0"], "at least 1"),
    ("evaluate", ["--policy", "/nope.policy"], "no policy file"),
])
def test_commands_refuse_bad_arguments_in_one_line(command, args, message):
    result = run(command, *args)
    assert result.returncode == 2
    assert message in result.stderr.strip().splitlines()[-1]
