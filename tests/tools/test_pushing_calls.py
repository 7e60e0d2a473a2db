"""The pushing-call analysis: the speed towards the other robot from a robot's sampled path, and each call's roles and bearing."""
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import pushing_calls  # noqa: E402

FRAME_US = 33_333


def walk(vx_mm_s, vy_mm_s=0.0, frames=31, jump_at=None):
    """(utime, x, y) samples of a robot walking from the origin at (vx, vy) mm/s, 30 Hz; with
    jump_at, it is put down 400 mm further on at that frame (a placement)."""
    h = []
    for k in range(frames):
        x, y = vx_mm_s * k * FRAME_US * 1e-6, vy_mm_s * k * FRAME_US * 1e-6
        if jump_at is not None and k >= jump_at:
            x += 400
        h.append((k * FRAME_US, x, y))
    return h


def test_walking_at_the_other_is_its_speed_and_backing_away_is_negative():
    h = walk(150)
    other = (h[-1][1] + 250, 0.0)
    assert abs(pushing_calls.towards(h, other, 0.5) - 150) < 1
    assert abs(pushing_calls.towards(walk(-80), (250.0, 0.0), 0.5) + 80) < 1


def test_passing_square_is_not_walking_at_it():
    h = walk(0, 300)
    assert abs(pushing_calls.towards(h, (250.0, h[-1][2]), 0.5)) < 1


def test_a_short_history_or_a_placement_in_the_window_says_nothing():
    assert pushing_calls.towards(walk(150, frames=5), (500.0, 0.0), 0.5) is None
    assert pushing_calls.towards(walk(150, jump_at=25), (2000.0, 0.0), 0.5) is None


def test_a_missing_or_foreign_log_is_one_line_and_a_failure(tmp_path):
    import subprocess
    foreign = tmp_path / "notes.txt"
    foreign.write_text("not an LCM log\n")
    script = Path(__file__).resolve().parents[2] / "tools" / "pushing_calls.py"
    for log, reason in ((tmp_path / "none.lcmlog", "No such file"), (foreign, "not a match log")):
        done = subprocess.run([sys.executable, str(script), str(log)], capture_output=True, text=True)
        assert done.returncode == 1 and done.stderr.count("\n") == 1, done.stderr
        assert done.stderr.startswith(f"pushing_calls: {log}: ") and reason in done.stderr


def test_a_call_names_both_roles_and_where_the_victim_stood(tmp_path):
    """A synthetic match log: team 0's striker walks at 150 mm/s into team 1's defender, who
    stands 90 degrees to its left (out of its sonars' and camera's middle); the referee calls
    team 0 #2 for pushing."""
    import touchline_paths
    sys.path[:0] = touchline_paths.lcm_python_dirs()
    import lcm
    from touchline import act_t, match_event_t, pose2d_t, robot_truth_t, world_truth_t

    def robot(team, player, x, y, theta):
        r = robot_truth_t()
        r.team, r.player, r.active = team, player, True
        for pose in ("body", "left_foot", "right_foot"):
            p = pose2d_t()
            p.x_mm, p.y_mm, p.theta_rad = x, y, theta
            setattr(r, pose, p)
        return r

    def act(team, player, role):
        a = act_t()
        a.team, a.player, a.localised = team, player, pose2d_t()
        a.team_message_size, a.team_message = 14, bytes([2, 0, role] + [0] * 11)
        return a

    log = tmp_path / "match.lcmlog"
    out = lcm.EventLog(str(log), "w", overwrite=True)
    out.write_event(0, "TL_ACT_0_2", act(0, 2, 2).encode())  # striker
    out.write_event(0, "TL_ACT_1_3", act(1, 3, 3).encode())  # defender
    for k in range(61):  # 2 s at 30 Hz: team 0 #2 walks along +y (its left) into the other
        t = world_truth_t()
        t.utime, t.frame = k * FRAME_US, k
        t.robots = [robot(0, 2, 0.0, 150.0 * k * FRAME_US * 1e-6 - 300.0, 0.0), robot(1, 3, 0.0, 250.0, math.pi)]
        t.num_robots = len(t.robots)
        out.write_event(t.utime, "TL_TRUTH", t.encode())
    e = match_event_t()
    e.utime, e.kind, e.team, e.player, e.text = 61 * FRAME_US, match_event_t.PENALTY, 0, 2, "pushing"
    out.write_event(e.utime, "TL_EVENT", e.encode())
    out.close()
    (call,) = pushing_calls.analyse(log)
    assert (call["pusher_role"], call["victim_role"]) == ("striker", "defender")
    assert abs(call["victim_bearing_deg"] - 90.0) < 1.0
    assert abs(call["pusher_towards_0.5"] - 150.0) < 1.0
    # It walked to its left; its head looked ahead (yaw 0), so the victim was never in view.
    assert abs(call["pusher_moving_deg"] - 90.0) < 1.0
    assert call["victim_in_view_s_ago"] is None


def test_a_robot_is_in_view_within_the_cone_about_the_head_and_within_reach():
    from types import SimpleNamespace as NS

    def truth(x, y, theta):
        return NS(body=NS(x_mm=x, y_mm=y, theta_rad=theta))

    me = truth(0.0, 0.0, 0.0)
    fov, reach = math.radians(60), 4000.0
    assert pushing_calls.in_view(me, truth(1000.0, 500.0, 0.0), 0.0, fov, reach)        # 27 deg left
    assert not pushing_calls.in_view(me, truth(1000.0, 700.0, 0.0), 0.0, fov, reach)    # 35 deg left
    assert pushing_calls.in_view(me, truth(0.0, 1000.0, 0.0), math.pi / 2, fov, reach)  # head turned to it
    assert not pushing_calls.in_view(me, truth(4500.0, 0.0, 0.0), 0.0, fov, reach)      # beyond reach
