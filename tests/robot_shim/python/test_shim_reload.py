"""Hot reload in a live match: a robot_shim whose Python behaviour raises stands; fixing the
file makes it walk within about a second of wall time, without restarting the shim."""
import math
import shutil
import time
from pathlib import Path

from touchline_harness import LCM_URL, ROBOT_SHIM, WALK_INI, Proc, start_world
from truth_listener import TruthListener

FIXTURES = Path(__file__).resolve().parent / "fixtures"
RELOAD_WITHIN_S = 1.5  # 250 ms between looks at the files, plus the import, plus slack


def body_xy(truth: TruthListener) -> tuple:
    body = next(r.body for r in truth.frames[-1].robots if r.team == 0 and r.player == 1)
    return body.x_mm, body.y_mm


def test_fixing_a_broken_behaviour_takes_effect_while_the_shim_runs(tmp_path):
    pydir = tmp_path / "py"
    pydir.mkdir()
    shutil.copy(FIXTURES / "raises.py", pydir / "behaviour.py")
    truth = TruthListener(LCM_URL)
    match = start_world(tmp_path, 1, 60, "--mode", "realtime", "--speed", "1")
    shim = Proc("robot_shim 0/1", [ROBOT_SHIM, "--team", 0, "--player", 1, "--behaviour", "py",
                                   "--python-dir", pydir, "--walk-config", WALK_INI, "--lcm-url", LCM_URL])
    match.robots["0/1"] = shim
    try:
        shim.wait_for_line("ValueError: deliberate failure in tick")
        truth.wait_for_frame(truth.frames[-1].frame + 15 if truth.frames else 15)
        standing = body_xy(truth)

        shutil.copy(FIXTURES / "walker.py", pydir / "behaviour.py")
        fixed_at = time.monotonic()
        shim.wait_for_line("robot_shim 0/1: reloaded behaviour (changed: behaviour.py)", timeout=10)
        latency = time.monotonic() - fixed_at
        print(f"reload latency: {latency:.3f} s")
        assert latency < RELOAD_WITHIN_S, f"reload took {latency:.2f} s"

        # 1 s of simulated time later the robot has walked off (150 mm/s asked).
        truth.wait_for_frame(truth.frames[-1].frame + 30)
        assert math.dist(body_xy(truth), standing) > 50
        assert shim.popen.poll() is None, "the shim must keep running"
        assert sum("Traceback" in line for line in shim.stderr) == 1, "\n".join(shim.stderr)
    finally:
        match.kill_all()
        truth.stop()
