"""The match statistics: the stuck detector (spinning on the spot or pressed against a wall), the
ball moving, the ball held between both teams, and the ball lying where the referee put it back."""
import math
import sys
from pathlib import Path

import pytest

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


def test_turning_on_a_walk_away_and_back_is_not_spinning_on_the_spot():
    half = match_stats.STUCK_WINDOW // 2
    away_and_back = [(min(i, 2 * half - i) * 10.0, 0.0, i * 0.1, True) for i in range(match_stats.STUCK_WINDOW)]
    assert away_and_back[half][0] == 500.0 and away_and_back[-1][0] < match_stats.STUCK_MOVE_MM
    assert match_stats.stuck_kind(away_and_back, EDGE_X, EDGE_Y) is None  # 10 rad, back where it began


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


def write_log(path, ball_at, robots, seconds=3.0, ball_out_frames=(), beliefs=None):
    """An LCM log of a match in PLAYING: TL_MATCH, TL_GAME, then `seconds` of TL_TRUTH at 30 Hz
    with the ball at `ball_at` (a point, or a function of the frame) and `robots`
    [(team, player, x, y)] standing; the referee's BALL_OUT (TL_EVENT) before each frame of
    `ball_out_frames`. With `beliefs` {(team, player): ((x, y, theta), (ball x, y), lost
    frames)}, each frame's TL_ACT_<team>_<player> of those robots says so."""
    import lcm
    from touchline import (act_t, game_state_t, match_config_t, match_event_t, pose2d_t, robot_truth_t,
                           world_truth_t)
    log = lcm.EventLog(str(path), "w", overwrite=True)
    match = match_config_t()
    match.field_length_mm, match.field_width_mm, match.border_mm = 6000, 4000, 700
    log.write_event(0, "TL_MATCH", match.encode())
    game = game_state_t()
    game.state = game_state_t.PLAYING
    log.write_event(0, "TL_GAME", game.encode())
    for frame in range(int(seconds * 30)):
        if frame in ball_out_frames:
            out = match_event_t()
            out.utime, out.kind, out.team, out.text = frame * 33333, match_event_t.BALL_OUT, -1, "ball out, put back"
            log.write_event(out.utime, "TL_EVENT", out.encode())
        truth = world_truth_t()
        truth.utime = frame * 33333
        truth.ball_x_mm, truth.ball_y_mm = ball_at(frame) if callable(ball_at) else ball_at
        for team, player, x, y in robots:
            r = robot_truth_t()
            r.team, r.player, r.active = team, player, True
            r.body, r.left_foot, r.right_foot = pose2d_t(), pose2d_t(), pose2d_t()
            r.body.x_mm, r.body.y_mm = x, y
            truth.robots.append(r)
        truth.num_robots = len(truth.robots)
        log.write_event(truth.utime, "TL_TRUTH", truth.encode())
        for (team, player), (pose, ball, lost) in (beliefs or {}).items():
            act = act_t()
            act.utime, act.frame, act.team, act.player = truth.utime, frame, team, player
            act.localised = pose2d_t()
            act.localised.x_mm, act.localised.y_mm, act.localised.theta_rad = pose
            act.ball_x_mm, act.ball_y_mm = ball
            act.ball_lost_frames, act.team_message = lost, b""
            log.write_event(act.utime, f"TL_ACT_{team}_{player}", act.encode())
    log.close()


def test_a_ball_held_between_both_teams_is_contested_and_one_team_alone_is_not(tmp_path):
    toe_to_toe = [(0, 2, -200.0, 0.0), (1, 2, 200.0, 0.0)]
    write_log(tmp_path / "held.lcmlog", (0.0, 0.0), toe_to_toe)
    held = match_stats.analyse_log(tmp_path / "held.lcmlog")
    # Still from the first second on (a ball seen for less than a second is not moving).
    assert held["playing_share"] == 1.0 and held["ball_moving_share"] == 0.0
    assert held["ball_contested_share"] == 1.0
    write_log(tmp_path / "lined_up.lcmlog", (0.0, 0.0), [(0, 2, -200.0, 0.0), (1, 2, 1000.0, 0.0)])
    assert match_stats.analyse_log(tmp_path / "lined_up.lcmlog")["ball_contested_share"] == 0.0


def test_a_ball_put_back_counts_until_it_first_moves_from_its_spot(tmp_path):
    # Rolling out for 1 s, put back 1 m behind, lying there 2 s, then rolled on at 10 mm a
    # frame: it leaves its spot by 100 mm 10 frames later (frame 100), of the 120.
    def ball(frame):
        if frame < 30:
            return (0.0, 1800.0 + 10.0 * frame)
        return (-1000.0 - 10.0 * max(0, frame - 90), 2000.0)
    write_log(tmp_path / "out.lcmlog", ball, [(0, 2, -1500.0, 1500.0)], seconds=4.0, ball_out_frames=(30,))
    stats = match_stats.analyse_log(tmp_path / "out.lcmlog")
    assert abs(stats["ball_put_back_still_share"] - 70 / 120) <= 1 / 40  # to a sample (every 3rd frame)
    write_log(tmp_path / "no_out.lcmlog", ball, [(0, 2, -1500.0, 1500.0)], seconds=4.0)
    assert match_stats.analyse_log(tmp_path / "no_out.lcmlog")["ball_put_back_still_share"] == 0.0


def test_a_ball_put_back_is_not_moving_in_the_second_after_the_jump(tmp_path):
    # Rolling out for 1 s at 300 mm/s (moving), then put back 1 m away and lying still for 2 s:
    # the jump is the referee's, not a second of play with the ball moving.
    def ball(frame):
        return (0.0, 1700.0 + 10.0 * frame) if frame < 30 else (-1000.0, 1600.0)
    write_log(tmp_path / "out.lcmlog", ball, [(0, 2, -1500.0, 1500.0)], seconds=3.0, ball_out_frames=(30,))
    stats = match_stats.analyse_log(tmp_path / "out.lcmlog")
    assert stats["ball_moving_share"] == 0.0 and stats["ball_put_back_still_share"] > 0.6


def test_the_ball_belief_is_how_far_off_a_robot_near_it_believes_it_relative_to_itself(tmp_path):
    # Robot 0.2 beside the ball believes itself 300 mm off and turned, and the ball where its
    # camera puts it from there: no error. Robot 1.2 (facing away) believes the ball 50 mm
    # further behind it; robot 0.3, lost, and robot 1.3, 1 m away, do not count.
    ball = (0.0, 0.0)
    robots = [(0, 2, -200.0, 0.0), (1, 2, 200.0, 0.0), (0, 3, 0.0, -300.0), (1, 3, 0.0, 1000.0)]
    beliefs = {(0, 2): ((100.0, 0.0, math.pi / 2), (100.0, 200.0), 0),  # 200 mm ahead, as it is
               (1, 2): ((200.0, 0.0, 0.0), (-50.0, 0.0), 2),           # 250 mm behind, not 200
               (0, 3): ((0.0, -300.0, 0.0), (0.0, 900.0), match_stats.BALL_SEEN_FRAMES + 1),
               (1, 3): ((0.0, 1000.0, 0.0), (0.0, 0.0), 0)}
    write_log(tmp_path / "belief.lcmlog", ball, robots, seconds=1.0, beliefs=beliefs)
    stats = match_stats.analyse_log(tmp_path / "belief.lcmlog")
    assert stats["ball_belief_error_median_mm"] == pytest.approx(25.0)  # 0 and 50 mm, every sample
    assert stats["ball_belief_error_p90_mm"] == pytest.approx(50.0)
    write_log(tmp_path / "no_acts.lcmlog", ball, robots, seconds=1.0)
    stats = match_stats.analyse_log(tmp_path / "no_acts.lcmlog")
    assert stats["ball_belief_error_median_mm"] is None and stats["ball_belief_error_p90_mm"] is None
