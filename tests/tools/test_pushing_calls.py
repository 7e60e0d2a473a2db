"""The pushing-call analysis' speed towards the other robot, from a robot's sampled path."""
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
