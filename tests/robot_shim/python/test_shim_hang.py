"""A Python behaviour that hangs in a live match: a tick() past --tick-timeout-ms is
interrupted, the robot stands and the match goes on, and the fixed file is loaded; SIGTERM
or SIGINT ends a shim stuck in tick() at once (128 + the signal's number), and one whose
behaviour swallows the interruption after the 2 s grace. Before, only SIGKILL ended it."""
import math
import shutil
import signal
from pathlib import Path

import pytest

from touchline_harness import LCM_URL, ROBOT_SHIM, WALK_INI, Proc, start_world
from truth_listener import TruthListener

FIXTURES = Path(__file__).resolve().parent / "fixtures"
STOP_WITHIN_S = 10  # only turns a shim that never stops into a failure (the grace is 2 s)


def start_shim(match, pydir: Path, *extra) -> Proc:
    shim = Proc("robot_shim 0/1", [ROBOT_SHIM, "--team", 0, "--player", 1, "--behaviour", "py",
                                   "--python-dir", pydir, "--walk-config", WALK_INI, "--lcm-url", LCM_URL, *extra])
    match.robots["0/1"] = shim
    return shim


def behaviour_dir(tmp_path: Path, fixture: str) -> Path:
    pydir = tmp_path / "py"
    pydir.mkdir()
    shutil.copy(FIXTURES / fixture, pydir / "behaviour.py")
    return pydir


def body_xy(truth: TruthListener) -> tuple:
    body = next(r.body for r in truth.frames[-1].robots if r.team == 0 and r.player == 1)
    return body.x_mm, body.y_mm


def test_a_hung_tick_is_interrupted_the_match_goes_on_and_the_fix_is_loaded(tmp_path):
    pydir = behaviour_dir(tmp_path, "loops_forever.py")
    truth = TruthListener(LCM_URL)
    match = start_world(tmp_path, 1, 60, "--mode", "realtime", "--speed", "1")
    shim = start_shim(match, pydir, "--tick-timeout-ms", 300)
    try:
        shim.wait_for_line("robot_shim 0/1: tick() timed out, not called again until the files change")
        shim.wait_for_line("touchline.TickTimeout: ran longer than 300 ms")
        # The robot answers at once from now on: within the world's 1 s robot timeout, so it
        # plays on, standing.
        truth.wait_for_frame(truth.frames[-1].frame + 30 if truth.frames else 30)
        standing = body_xy(truth)

        shutil.copy(FIXTURES / "walker.py", pydir / "behaviour.py")
        shim.wait_for_line("robot_shim 0/1: reloaded behaviour (changed: behaviour.py)", timeout=10)
        truth.wait_for_frame(truth.frames[-1].frame + 30)
        assert math.dist(body_xy(truth), standing) > 50  # walking: the fix took
        assert shim.popen.poll() is None, "the shim must keep running"
        assert sum("Traceback" in line for line in shim.stderr) == 1, "\n".join(shim.stderr)
        assert not any("no answer within" in line for line in match.world.stderr), "\n".join(match.world.stderr)
    finally:
        match.kill_all()
        truth.stop()


@pytest.mark.parametrize("fixture", ["loops_forever.py", "sleeps_forever.py"])
@pytest.mark.parametrize("sig, status", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_a_stop_signal_ends_a_shim_stuck_in_tick(tmp_path, fixture, sig, status):
    pydir = behaviour_dir(tmp_path, fixture)
    match = start_world(tmp_path, 1, 60)
    shim = start_shim(match, pydir, "--tick-timeout-ms", 0)  # no timeout: stuck for good
    try:
        shim.wait_for_line(": in tick")
        shim.popen.send_signal(sig)
        assert shim.wait(STOP_WITHIN_S) == status, "\n".join(shim.stderr)
        # Ended by interrupting Python, not by the grace period, and nothing to report.
        assert not any("still running" in line or "Traceback" in line for line in shim.stderr), \
            "\n".join(shim.stderr)
    finally:
        match.kill_all()


def test_a_behaviour_that_swallows_the_interruption_is_cut_short_after_the_grace(tmp_path):
    pydir = behaviour_dir(tmp_path, "swallows_interrupts.py")
    match = start_world(tmp_path, 1, 60)
    shim = start_shim(match, pydir, "--tick-timeout-ms", 0)
    try:
        shim.wait_for_line(": in tick")
        shim.popen.send_signal(signal.SIGTERM)
        assert shim.wait(STOP_WITHIN_S) == 143, "\n".join(shim.stderr)
        assert shim.stderr[-1] == ("robot_shim 0/1: still running 2 s after the stop signal "
                                   "(stuck in the behaviour?); exiting"), "\n".join(shim.stderr)
    finally:
        match.kill_all()
