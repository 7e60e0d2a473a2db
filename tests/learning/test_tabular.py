"""The thesis's learners (touchline_rl.tabular, cases): Algorithm 3.1 by hand, the trace's
length, case interpolation, shortest paths on a grid world; one short run on the real walk;
the train_thesis script end to end."""
import math
import random
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "learning"))

from touchline_rl.cases import UniformCases  # noqa: E402
from touchline_rl.tabular import CaseBasedTraceQLearner, QLearner, TraceQLearner  # noqa: E402


# --- Algorithm 3.1 on a hand-worked example ------------------------------------------------

def chain_learner(kind, alpha):
    """States 0, 1, 2 in a row; action 0 walks on, action 1 is preset far worse so that
    max over actions is action 0's value."""
    learner = kind(3, 2, alpha, gamma=1.0, epsilon=0.0)
    for row in learner.q:
        row[1] = -10.0
    return learner


def test_algorithm_3_1_replays_the_trace_backwards():
    learner = chain_learner(TraceQLearner, alpha=0.5)
    learner.learn(0, 0, -1.0, 1)     # Q0 = 0.5 * -1 = -0.5
    assert learner.q[0][0] == pytest.approx(-0.5)
    learner.learn(1, 0, -2.0, 2)     # Q1 = -1; replay 0: Q0 = -0.5 + 0.5 * (-1 + -1 + 0.5) = -1.25
    assert [learner.q[s][0] for s in (0, 1)] == pytest.approx([-1.25, -1.0])
    learner.learn(2, 0, -3.0, None)  # Q2 = -1.5 (terminal: max is 0)
    # replay 1: Q1 = -1 + 0.5 * (-2 + -1.5 + 1) = -2.25; replay 0: Q0 = -1.25 + 0.5 * (-1 + -2.25 + 1.25) = -2.25
    assert [learner.q[s][0] for s in (0, 1, 2)] == pytest.approx([-2.25, -2.25, -1.5])
    assert [learner.q[s][1] for s in (0, 1, 2)] == [-10.0] * 3  # actions not taken are untouched


def test_plain_q_learning_updates_only_the_current_state():
    learner = chain_learner(QLearner, alpha=0.5)
    for state, reward, following in ((0, -1.0, 1), (1, -2.0, 2), (2, -3.0, None)):
        learner.learn(state, 0, reward, following)
    assert [learner.q[s][0] for s in (0, 1, 2)] == pytest.approx([-0.5, -1.0, -1.5])


def test_the_trace_keeps_exactly_the_last_20_and_replays_only_them():
    learner = TraceQLearner(30, 1, 0.3, gamma=1.0, epsilon=0.0)
    for state in range(24):
        learner.learn(state, 0, -1.0, state + 1)
    before = [row[0] for row in learner.q]
    learner.learn(24, 0, -1.0, 25)
    assert [s for s, _, _ in learner.trace] == list(range(5, 25))
    after = [row[0] for row in learner.q]
    changed = [s for s in range(30) if after[s] != before[s]]
    assert changed == list(range(5, 25))


def test_end_episode_clears_the_trace():
    learner = TraceQLearner(3, 1, 0.3)
    learner.learn(0, 0, -1.0, 1)
    learner.end_episode()
    assert len(learner.trace) == 0


# --- uniform cases -------------------------------------------------------------------------

HEADING_CASES = UniformCases((0.0, 0.0, 0.0), (1000.0, 1000.0, 2 * math.pi), (11, 11, 8), periodic=(False, False, True))


def test_case_weights_are_positive_and_sum_to_one():
    rng = random.Random(1)
    for _ in range(200):
        state = (rng.uniform(0, 1000), rng.uniform(0, 1000), rng.uniform(-math.pi, math.pi))
        indices, weights = HEADING_CASES.encode(state)
        assert all(w > 0 for w in weights) and len(set(indices)) == len(indices) <= 8
        assert sum(weights) == pytest.approx(1.0)


def test_a_state_on_a_case_is_that_case_alone():
    for index in (0, 7, 8, 500, HEADING_CASES.n_cases - 1):
        assert HEADING_CASES.encode(HEADING_CASES.point(index)) == ((index,), (1.0,))


def test_interpolation_is_linear_between_cases_and_wraps_the_heading():
    corner = (10 * 11 + 10) * 8  # the cases at x = y = 1000 mm, heading 0 .. 7 pi/4
    indices, weights = HEADING_CASES.encode((1000.0, 1000.0, 2 * math.pi - math.pi / 8))  # halfway 7 pi/4 -> 2 pi
    assert dict(zip(indices, weights)) == pytest.approx({corner + 7: 0.5, corner: 0.5})
    indices, weights = HEADING_CASES.encode((25.0, 0.0, 0.0))  # a quarter of the way from x = 0 to x = 100
    assert dict(zip(indices, weights)) == pytest.approx({0: 0.75, 11 * 8: 0.25})


def test_case_based_update_goes_to_the_cases_by_their_weights():
    cases = UniformCases((0.0,), (2.0,), (3,))
    learner = CaseBasedTraceQLearner(cases.n_cases, 1, 0.5, gamma=1.0, epsilon=0.0)
    state = cases.encode((0.25,))  # case 0 weight 0.75, case 1 weight 0.25
    learner.learn(state, 0, -4.0, None)  # error -4: q0 += 0.5 * 0.75 * -4, q1 += 0.5 * 0.25 * -4
    assert [row[0] for row in learner.q] == pytest.approx([-1.5, -0.5, 0.0])
    assert learner.values(state)[0] == pytest.approx(0.75 * -1.5 + 0.25 * -0.5)


# --- shortest paths on a grid world --------------------------------------------------------

SIZE, GOAL = 5, (4, 4)
MOVES = ((1, 0), (-1, 0), (0, 1), (0, -1))


def grid_step(cell, action):
    """Deterministic 5 x 5 grid: a move into the wall stays put; -1 a step; the goal ends it."""
    x, y = cell[0] + MOVES[action][0], cell[1] + MOVES[action][1]
    cell = (min(max(x, 0), SIZE - 1), min(max(y, 0), SIZE - 1))
    return cell, -1.0, cell == GOAL


def train_grid(learner, encode, episodes=400, seed=3):
    rng = random.Random(seed)
    for _ in range(episodes):
        cell = (rng.randrange(SIZE), rng.randrange(SIZE))
        for _ in range(100):
            if cell == GOAL:
                break
            action = learner.act(encode(cell))
            following, reward, done = grid_step(cell, action)
            learner.learn(encode(cell), action, reward, None if done else encode(following))
            cell = following
        learner.end_episode()


def greedy_path_length(learner, encode, cell):
    for steps in range(3 * SIZE * SIZE):
        if cell == GOAL:
            return steps
        cell, _, _ = grid_step(cell, learner.act(encode(cell), greedy=True))
    return None


@pytest.mark.parametrize("kind", ["plain", "traces", "case-based"])
def test_each_learner_finds_the_shortest_path(kind):
    if kind == "case-based":
        cases = UniformCases((0.0, 0.0), (SIZE - 1.0, SIZE - 1.0), (SIZE, SIZE))
        learner, encode = CaseBasedTraceQLearner(cases.n_cases, 4, 0.1, gamma=1.0, seed=1), cases.encode
    else:
        learner = (QLearner if kind == "plain" else TraceQLearner)(SIZE * SIZE, 4, 0.3, gamma=1.0, seed=1)
        encode = lambda cell: cell[0] * SIZE + cell[1]  # noqa: E731
    train_grid(learner, encode, episodes=400 if kind == "traces" else 2000)
    for x in range(SIZE):
        for y in range(SIZE):
            assert greedy_path_length(learner, encode, (x, y)) == (GOAL[0] - x) + (GOAL[1] - y), (x, y)


# --- "converged" ---------------------------------------------------------------------------

def curve(*rates):
    return [{"episode": 100 * (i + 1), "greedy_success": r} for i, r in enumerate(rates)]


def test_converged_means_the_curve_reached_90_percent_and_stayed():
    from touchline_rl.thesis_train import converged_at
    assert converged_at(curve(0.5, 0.95, 0.8, 0.92, 0.93, 0.91)) == 400  # from the 4th checkpoint on
    assert converged_at(curve(0.95, 0.95, 0.95, 0.85)) is None  # fell back at the end
    assert converged_at(curve(0.2, 0.95, 0.95)) is None  # held for two checkpoints, not three


# --- the real walk -------------------------------------------------------------------------

def test_traces_on_the_real_walk_beat_the_untrained_policy():
    """A 400 mm area, 100 mm cells, the target in its middle: 2000 episodes (~2 s)."""
    from touchline_rl import thesis
    from touchline_rl.envs import GoToPoseEnv

    size = 400.0
    area = thesis.Area(size_mm=size, cell_mm=100.0, max_steps=300, target=(200.0, 200.0, 0.0))
    target = area.target

    def env():
        return GoToPoseEnv(start_region=((0, size), (0, size)), bounds=(0, size, 0, size), success_distance_mm=100.0,
                           success_heading_rad=None, max_steps=300, out_of_bounds_reward=-300.0)

    rng = random.Random(5)
    starts = [(rng.uniform(0, size), rng.uniform(0, size), rng.uniform(-math.pi, math.pi)) for _ in range(60)]
    learner, encode = thesis.make_learner(area, thesis.METHODS["traces"], seed=4)
    evaluation = env()
    untrained, _ = thesis.evaluate(evaluation, learner, encode, target, starts)
    training = env()
    training.reset(seed=4, options={"target": target})
    for _ in range(2000):
        thesis.run_episode(training, learner, encode, target)
    trained, _ = thesis.evaluate(evaluation, learner, encode, target, starts)
    assert trained >= untrained + 0.1, (untrained, trained)


# --- the script ----------------------------------------------------------------------------

def test_train_thesis_writes_the_table_and_the_curves(tmp_path):
    out = tmp_path / "thesis"
    run = subprocess.run([str(REPO / "learning" / "train_thesis"), "--episodes", "2", "--eval-starts", "3",
                          "--out", str(out)], capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    table = (out / "results.md").read_text()
    for method in ("plain", "traces", "case-based"):
        assert f"| {method} |" in table
    import json
    results = json.loads((out / "results.json").read_text())["results"]
    assert [r["method"] for r in results] == ["plain", "traces", "case-based"]
    assert all(r["episodes"] == 2 and r["eval_starts"] == 3 for r in results)
    assert (out / "curves.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_train_thesis_rejects_bad_arguments(tmp_path):
    run = subprocess.run([str(REPO / "learning" / "train_thesis"), "--episodes", "0", "--out", str(tmp_path)],
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 2
    assert "--episodes" in run.stderr.strip().splitlines()[-1]
