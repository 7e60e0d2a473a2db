"""One match of a sweep: runs the launcher (tools/launch.py) as a child process, in a private
network namespace of its own unless the match's launcher options say --host-network, so
matches played side by side never share a bus; then reads its --json summary and its LCM log
(possession and stuck time, match_stats.py) into one flat row of the sweep's table. Writes
only into a temporary folder it removes (or into `keep_logs`, the match's log).

A match that fails is a row with status 'failed' and its error, never an exception; a match
whose robot_shim died (launcher exit 3) played to its end and is a row with status
'shim_died'. Runs the same in a local worker thread and in a Ray task.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
from collections import Counter
from pathlib import Path

import match_stats
import touchline_paths
from sweep_grid import cell_label, launcher_args

LAUNCHER = Path(__file__).resolve().parent / "launch.py"  # beside this file, also when installed
EXIT_SHIM_DIED = 3  # tools/launch.py: a robot_shim died, the match played to its end
STOP_POLL_S = 0.2   # how often a running match checks whether the sweep is stopping

# The table's columns, in order: a row per match.
COLUMNS = ["cell", "label", "team0", "team1", "settings", "variant", "seed", "status", "exit_code", "error",
           "goals0", "goals1", "goal_difference", "penalties0", "penalties1", "falls0", "falls1",
           "possession0", "possession_frames0", "possession_frames1", "stuck_s0", "stuck_s1",
           "ball_moving_share", "playing_share", "ball_contested_share", "ball_put_back_still_share",
           "ball_belief_error_median_mm", "ball_belief_error_p90_mm",
           "localisation_worst_mm0", "localisation_worst_mm1",
           "sim_s", "wall_s", "rtf", "truth_hash", "penalty_kinds"]


def play(match: dict, build_dir: Path, keep_logs: Path | None = None, stop: threading.Event | None = None,
         python: str = sys.executable) -> dict:
    """Plays `match` (a sweep_grid.expand() entry) and returns its row. `stop` set while it
    plays stops the launcher (SIGTERM: it stops every process of the match) and the row says
    'interrupted'; so does a KeyboardInterrupt (a cancelled Ray task), which then goes on up."""
    row = {c: "" for c in COLUMNS}
    row.update(cell=match["cell"], label=cell_label(match), team0=match["team0"] or "", team1=match["team1"] or "",
               settings=" ".join(match["settings"]), variant=match["variant"], seed=match["seed"])
    env = dict(os.environ)
    if "--host-network" not in match["launch"]:
        env.pop("TOUCHLINE_IN_NETNS", None)  # a namespace of its own even when the sweep runs in one
    work = Path(tempfile.mkdtemp(prefix="touchline-sweep-"))
    try:
        summary_path = work / "summary.json"
        command = [python, str(LAUNCHER), "--build-dir", str(build_dir), "--json",
                   str(summary_path), "--log-dir", str(work), "--no-progress", *launcher_args(match)]
        launcher = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                                    start_new_session=True)  # a terminal's Ctrl-C reaches the sweep, which stops it
        try:
            out, err = communicate(launcher, stop)
        except BaseException:
            stop_launcher(launcher)
            raise
        row["exit_code"] = launcher.returncode
        if out is None:
            return {**row, "status": "failed", "error": "interrupted"}
        if launcher.returncode not in (0, EXIT_SHIM_DIED) or not summary_path.exists():
            lines = (err.strip() or out.strip() or "no output").splitlines()
            return {**row, "status": "failed", "error": lines[-1]}
        row.update(from_summary(json.loads(summary_path.read_text())))
        row["status"] = "ok" if launcher.returncode == 0 else "shim_died"
        logs = sorted(work.glob("*.lcmlog"))
        if logs:
            for types in touchline_paths.lcm_python_dirs(build_dir):  # the match's own message types
                if types not in sys.path:
                    sys.path.insert(0, types)
            try:
                row.update(from_log(match_stats.analyse_log(logs[0])))
            except Exception as e:  # noqa: BLE001 - a log we cannot read leaves those columns empty, says why
                row["error"] = f"log analysis: {e}"
            if keep_logs is not None:
                keep_logs.mkdir(parents=True, exist_ok=True)
                shutil.move(logs[0], keep_logs / f"cell{match['cell']}_seed{match['seed']}.lcmlog")
        return row
    finally:
        shutil.rmtree(work, ignore_errors=True)


def communicate(launcher: subprocess.Popen, stop: threading.Event | None) -> tuple[str | None, str | None]:
    """The launcher's output once it ends; (None, None) if `stop` was set first (it is stopped)."""
    while True:
        try:
            return launcher.communicate(timeout=STOP_POLL_S)
        except subprocess.TimeoutExpired:
            if stop is not None and stop.is_set():
                stop_launcher(launcher)
                return None, None


def stop_launcher(launcher: subprocess.Popen) -> None:
    """SIGTERM: the launcher stops every process of its match and exits; SIGKILL if it hangs."""
    if launcher.poll() is None:
        launcher.terminate()
        try:
            launcher.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            launcher.kill()
            launcher.communicate()


def from_summary(summary: dict) -> dict:
    """The table's columns from the launcher's --json summary."""
    goals = summary["score"]
    penalties = Counter(p["team"] for p in summary["penalties"])
    falls = Counter(f["team"] for f in summary["falls"])
    kinds = Counter(f"{p['team']}:{p['kind']}" for p in summary["penalties"])
    # Each team's worst robot by the world's localisation_rms_mm (belief against truth over
    # the frames it was on the field): issue #17's "worst robot RMS" of a refereed match.
    worst = [max((r["localisation_rms_mm"] for r in summary["robots"] if r["team"] == team), default="")
             for team in (0, 1)]
    return {"goals0": goals[0], "goals1": goals[1], "goal_difference": goals[0] - goals[1],
            "penalties0": penalties[0], "penalties1": penalties[1], "falls0": falls[0], "falls1": falls[1],
            "sim_s": summary["sim_s"], "wall_s": summary["wall_s"], "rtf": summary["rtf"],
            "truth_hash": summary["truth_hash"], "penalty_kinds": json.dumps(dict(kinds.most_common())),
            "localisation_worst_mm0": worst[0], "localisation_worst_mm1": worst[1]}


def from_log(stats: dict) -> dict:
    """The table's columns from match_stats.analyse_log(): possession share of team 0 (empty
    when no robot had the ball), stuck seconds, the share of the match the ball moved in play, the
    share in PLAYING, the share it sat held between both teams in play and the share it lay
    where the referee put it back after it went out, and how far robots near the ball believe
    it from where it is (median and 90th percentile; empty without a sample)."""
    frames = stats["possession_frames"]
    share = frames[0] / sum(frames) if sum(frames) else ""
    return {"possession0": share, "possession_frames0": frames[0], "possession_frames1": frames[1],
            "stuck_s0": stats["stuck_s"][0], "stuck_s1": stats["stuck_s"][1],
            "ball_moving_share": stats["ball_moving_share"], "playing_share": stats["playing_share"],
            "ball_contested_share": stats["ball_contested_share"],
            "ball_put_back_still_share": stats["ball_put_back_still_share"],
            **{key: "" if stats[key] is None else stats[key]
               for key in ("ball_belief_error_median_mm", "ball_belief_error_p90_mm")}}
