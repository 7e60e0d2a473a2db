"""tools/sweep end to end: a small grid played side by side (each match in a network
namespace of its own), a failed match as a row, a bad grid refused in one line, and the same
sweep as Ray tasks on a local Ray instance."""
import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

from conftest import cmdline, descendants, wait_until_gone

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
SWEEP = [sys.executable, str(ROOT / "tools" / "sweep.py"), "--build-dir", str(BUILD), "--no-progress"]
SHORT = ["--", "--team-size", "1", "--duration", "8"]  # every match: 1 v 1, 8 simulated seconds
WAIT_S = 300


def run(*args):
    env = {**os.environ, "RAY_USAGE_STATS_ENABLED": "0"}
    result = subprocess.run([*SWEEP, *map(str, args)], capture_output=True, text=True, timeout=WAIT_S, env=env)
    return result.returncode, result.stdout + result.stderr


def table(out):
    with open(out / "matches.csv") as f:
        return list(csv.DictReader(f))


def test_two_matches_side_by_side_make_one_table(tmp_path):
    # Two grid cells that are the same match (walkcycle is the default engine), played at
    # once: on a shared bus they would see each other's robots; each in its own namespace
    # they play the same match, bit for bit.
    rc, output = run("--out", tmp_path, "--workers", 2, "--seeds", 3, "--variant", "",
                     "--variant", "--walk-engine walkcycle", *SHORT)
    assert rc == 0, output
    rows = table(tmp_path)
    assert [(r["cell"], r["seed"], r["status"]) for r in rows] == [("0", "3", "ok"), ("1", "3", "ok")], output
    first, second = rows
    assert first["truth_hash"] and first["truth_hash"] == second["truth_hash"]
    for column in ("goals0", "goals1", "penalties0", "falls0", "possession_frames0", "stuck_s0", "stuck_s1", "sim_s",
                   "wall_s", "rtf"):
        assert first[column] != "", column
    assert float(first["sim_s"]) >= 8 and float(first["rtf"]) > 0
    assert 0 < float(first["localisation_worst_mm0"]) < 5000 and 0 < float(first["localisation_worst_mm1"]) < 5000
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert [(c["cell"], c["matches"], c["failed"]) for c in summary] == [(0, 1, 0), (1, 1, 0)]
    assert (tmp_path / "summary.png").exists() and (tmp_path / "summary.csv").exists()
    assert "sweep: 2/2" in output


def test_a_failed_match_is_a_row_with_its_error(tmp_path):
    rc, output = run("--out", tmp_path, "--workers", 2, "--variant", "", "--variant",
                     f"--config {tmp_path / 'no-such-world.ini'}", *SHORT)
    assert rc == 1, output
    played, failed = table(tmp_path)
    assert played["status"] == "ok" and played["goals0"] != ""
    # The launcher refuses the missing config before anything starts: bad input, exit 2.
    assert failed["status"] == "failed" and failed["exit_code"] == "2" and failed["goals0"] == ""
    assert "sim_world" in failed["error"], failed["error"]
    assert "1 of 2 matches failed" in output


def test_a_grid_the_launcher_refuses_is_one_line(tmp_path):
    rc, output = run("--out", tmp_path, "--", "--team-size", "9")
    assert rc == 2 and output.strip().count("\n") == 0 and "--team-size must be 1..7" in output, output
    rc, output = run("--out", tmp_path, "--seeds", "5-1")
    assert rc == 2 and "backwards" in output, output
    assert not tmp_path.joinpath("matches.csv").exists()


def test_the_same_sweep_on_a_local_ray_instance(tmp_path):
    rc, output = run("--out", tmp_path / "local", "--workers", 2, "--seeds", "1-2", *SHORT)
    assert rc == 0, output
    rc, output = run("--out", tmp_path / "ray", "--ray", "local", "--workers", 2, "--seeds", "1-2", *SHORT)
    assert rc == 0, output
    assert "on Ray (local)" in output
    local, ray = table(tmp_path / "local"), table(tmp_path / "ray")
    assert [r["status"] for r in ray] == ["ok", "ok"]
    assert [r["truth_hash"] for r in ray] == [r["truth_hash"] for r in local]  # the same matches, bit for bit
    assert ray[0]["possession_frames0"] != ""


def test_ctrl_c_stops_every_match_and_keeps_what_finished(tmp_path):
    args = ["--out", tmp_path, "--workers", 2, "--seeds", "1-4", "--", "--team-size", 1, "--duration", 600]
    sweep = subprocess.Popen([*SWEEP, *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             start_new_session=True)
    try:
        deadline = time.monotonic() + WAIT_S
        while len(worlds := [p for p in descendants(sweep.pid) if "sim_world" in cmdline(p)]) < 2:
            assert time.monotonic() < deadline and sweep.poll() is None, "the sweep never started two matches"
            time.sleep(0.05)  # polling /proc for the matches to start, not hiding a race
        under = descendants(sweep.pid)
        sweep.send_signal(signal.SIGINT)
        output, _ = sweep.communicate(timeout=WAIT_S)
    finally:
        if sweep.poll() is None:
            os.killpg(sweep.pid, signal.SIGKILL)
    assert sweep.returncode == 130, output
    assert wait_until_gone(under) == [], "processes of the sweep outlived it"
    rows = table(tmp_path)
    assert len(rows) == 2 and all(r["status"] == "failed" and r["error"] == "interrupted" for r in rows), rows
    assert "interrupted" in output
