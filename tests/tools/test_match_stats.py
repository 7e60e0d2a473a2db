"""The match statistics' stuck detector: spinning on the spot or pressed against a wall."""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import match_stats  # noqa: E402

EDGE_X, EDGE_Y = 3700.0, 2700.0  # SPL 2011 carpet


def samples(x, y, theta_step=0.0, dx=0.0):
    return [(x + i * dx, y, i * theta_step, True) for i in range(match_stats.STUCK_WINDOW)]


def test_spinning_on_the_spot_is_stuck():
    assert match_stats.stuck_kind(samples(0, 0, theta_step=0.1), EDGE_X, EDGE_Y) == "spin"  # 10 rad in 10 s


def test_standing_against_the_wall_is_stuck():
    assert match_stats.stuck_kind(samples(3600, 0), EDGE_X, EDGE_Y) == "wall"


def test_standing_in_the_field_or_walking_is_not():
    assert match_stats.stuck_kind(samples(0, 0), EDGE_X, EDGE_Y) is None
    assert match_stats.stuck_kind(samples(3400, 0, dx=-2), EDGE_X, EDGE_Y) is None  # walks away from the wall
    assert match_stats.stuck_kind(samples(0, 0, theta_step=0.05), EDGE_X, EDGE_Y) is None  # 5 rad: less than a full turn


def test_the_episode_listing_names_how_a_robot_is_stuck():
    assert match_stats.stuck_kind(samples(0, 0, theta_step=0.1), EDGE_X, EDGE_Y) == "spin"
    assert match_stats.stuck_kind(samples(3600, 0), EDGE_X, EDGE_Y) == "wall"
    assert match_stats.stuck_kind(samples(3600, 0, theta_step=0.1), EDGE_X, EDGE_Y) == "spin"  # spinning at a wall
    assert match_stats.stuck_kind(samples(0, 0), EDGE_X, EDGE_Y) is None


def path(step_mm, samples=match_stats.SAMPLES_PER_S + 1):
    return [(i * step_mm, 0.0) for i in range(samples)]


def test_a_rolling_ball_is_moving():
    assert match_stats.ball_moving(path(match_stats.BALL_MOVING_MM / match_stats.SAMPLES_PER_S))


def test_a_wedged_or_new_ball_is_not_moving():
    assert not match_stats.ball_moving(path(0))  # still
    assert not match_stats.ball_moving(path(0.9 * match_stats.BALL_MOVING_MM / match_stats.SAMPLES_PER_S))
    assert not match_stats.ball_moving(path(100, samples=match_stats.SAMPLES_PER_S))  # under a second seen
    jitter = [(40.0 * (i % 2), 0.0) for i in range(match_stats.SAMPLES_PER_S + 1)]
    assert not match_stats.ball_moving(jitter)  # back and forth between two feet goes nowhere


def test_a_missing_or_foreign_log_is_one_line_and_a_failure(tmp_path, capsys):
    foreign = tmp_path / "notes.txt"
    foreign.write_text("not an LCM log\n")
    for log, reason in ((tmp_path / "none.lcmlog", "No such file"), (foreign, "not a match log")):
        assert match_stats.main([str(log)]) == 1
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and err.startswith(f"match_stats: {log}: ") and reason in err, err
