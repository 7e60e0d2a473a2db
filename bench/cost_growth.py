"""How a match's cost grows with its robots (issue #14): real-time factor and exchanges per
second (robot answers per wall second) of 2, 4, 8, 10 and 14 robots (1 v 1 up to 7 v 7 on
the modern field), lockstep against in-process, C++ (cpp:Team) against Python (py:Team),
each next to two limits measured in the same run: the LCM cap (33 333 us per frame over the
round trip to n responders, touchline_bench --floor-only) and the physics limit (simulated
seconds per wall second spent in the world alone, sensing and stepping, from the in-process
C++ run). First the goal of the in-process mode: 4 v 4 on one core, C++ Team >= 400x and
Python Team >= 100x real time.

Every match is tools/launch.py's, as a user plays it (--json summary). In-process runs are
pinned to one core (taskset -c 0); lockstep runs may use every core, one process per robot.
Beside each real-time factor (simulated s per wall s) a CPU one (simulated s per CPU s),
which other load on the machine hardly moves: in-process, the match loop's own CPU time
(touchline_match's cpu_s); lockstep, every process's (world, shims and launcher, start-up
included: what a machine running many matches pays).
Run it through bench/cost_growth (a private network namespace: LCM stays on its loopback).
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ROBOTS = (2, 4, 8, 10, 14)
GOALS = {"cpp:Team": 400, "py:Team": 100}  # in-process 4 v 4 on one core, x real time
FRAMES_PER_S = 30


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build-dir", type=Path, default=ROOT / "build")
    p.add_argument("--duration", type=float, default=60, help="simulated seconds per match (default 60)")
    p.add_argument("--repeat", type=int, default=3, help="matches per cell, the median reported (default 3)")
    p.add_argument("--robots", type=int, nargs="+", default=list(ROBOTS), help="robot counts (even, 2..14)")
    p.add_argument("--config", type=Path, default=ROOT / "config" / "spl2020.ini", help="the table's field")
    p.add_argument("--no-lockstep", action="store_true", help="in-process columns and limits only")
    p.add_argument("--json", type=Path, help="also write every figure here")
    args = p.parse_args(argv)
    if args.duration <= 0 or args.repeat < 1:
        p.error("--duration must be > 0 and --repeat >= 1")
    if any(n < 2 or n > 14 or n % 2 for n in args.robots):
        p.error("--robots must be even numbers in 2..14")
    for binary in ("touchline_match", "sim_world", "robot_shim"):
        if not (args.build_dir / "bin" / binary).exists():
            p.error(f"{args.build_dir / 'bin' / binary} is not built (tools/setup)")
    if not (args.build_dir / "bench" / "touchline_bench").exists():
        p.error(f"{args.build_dir / 'bench' / 'touchline_bench'} is not built (cmake --build build --target touchline_bench)")
    return args


def match(args, tmp: Path, team: str, robots: int, in_process: bool, config: Path) -> dict:
    """Medians over --repeat matches: rtf, cpu_rtf, physics_rtf (in-process only)."""
    runs = []
    for i in range(args.repeat):
        out = tmp / f"summary_{i}.json"
        command = [sys.executable, str(ROOT / "tools" / "launch.py"), "--build-dir", str(args.build_dir),
                   "--team0", team, "--team1", team, "--team-size", str(robots // 2), "--config", str(config),
                   "--duration", str(args.duration), "--seed", str(i + 1), "--no-log", "--no-progress",
                   "--json", str(out), *(["--in-process"] if in_process else [])]
        if in_process:
            command = ["taskset", "-c", "0", *command]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        result = subprocess.run(command, capture_output=True, text=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if result.returncode != 0:
            raise SystemExit(f"cost_growth: {' '.join(command)} failed ({result.returncode}): "
                             f"{(result.stderr or result.stdout).strip().splitlines()[-1:]}")
        summary = json.loads(out.read_text())
        if not in_process:  # every process of the match, waited for by the launcher
            cpu_s = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            summary["cpu_rtf"] = summary["sim_s"] / cpu_s
        runs.append(summary)
    medians = {key: statistics.median(s[key] for s in runs) for key in ("rtf", "cpu_rtf")}
    if in_process:
        medians["physics_rtf"] = statistics.median(s["physics_rtf"] for s in runs)
    return medians


def lcm_caps(args, robots: list[int]) -> dict:
    command = [str(args.build_dir / "bench" / "touchline_bench"), "--floor-only", "--responders", *map(str, robots)]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit(f"cost_growth: {' '.join(command)} failed: {result.stderr.strip()}")
    return {f["responders"]: f for f in map(json.loads, result.stdout.splitlines())}


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    if os.environ.get("TOUCHLINE_IN_NETNS") != "1" and not args.no_lockstep:
        netns = ROOT / "tools" / "netns"  # lockstep and the LCM cap on a loopback of their own
        os.execv(netns, [str(netns), sys.executable, __file__, *argv])
    tmp = Path(tempfile.mkdtemp(prefix="touchline-cost-"))
    figures: dict = {"duration_s": args.duration, "repeat": args.repeat, "nproc": os.cpu_count(), "goal": {},
                     "table": []}
    try:
        print(f"In-process 4 v 4 ({ROOT / 'config' / 'spl2011.ini'}, the launcher's default), one core, "
              f"{args.duration:.0f} s simulated, median of {args.repeat}:", flush=True)
        for team, goal in GOALS.items():
            s = match(args, tmp, team, 8, True, ROOT / "config" / "spl2011.ini")
            figures["goal"][team] = {**s, "goal_rtf": goal}
            print(f"  {team:<9} x{s['rtf']:7.1f} real time (x{s['cpu_rtf']:7.1f} per CPU second), goal x{goal}: "
                  f"{s['rtf'] / goal:5.2f} of it ({s['cpu_rtf'] / goal:5.2f} by CPU time); the world alone "
                  f"x{s['physics_rtf']:.1f}", flush=True)
        caps = {} if args.no_lockstep else lcm_caps(args, args.robots)
        print(f"\nCost growth on {args.config.name}, {args.duration:.0f} s simulated, median of {args.repeat} "
              f"(RTF = x real time; CPU = simulated s per CPU s; ex/s = robot answers per wall second; in-process "
              f"on one core, lockstep on {os.cpu_count()} cores; LCM cap and physics limit as RTF)")
        modes = [("in-process", True)] + ([] if args.no_lockstep else [("lockstep", False)])
        header = f"{'robots':>6} {'LCM cap':>8} {'physics':>8}"
        for mode, _ in modes:
            for team in GOALS:
                header += f" {mode + ' ' + team.split(':')[0]:>24}"
        print(header + "\n" + " " * 24 + "".join(f" {'RTF':>7} {'CPU':>7} {'ex/s':>8}" for _ in range(2 * len(modes))),
              flush=True)
        for n in args.robots:
            row = {"robots": n, "lcm_cap_rtf": caps[n]["cap_rtf"] if caps else None,
                   "lcm_floor_us": caps[n]["median_us"] if caps else None}
            cells = ""
            for mode, in_process in modes:
                for team in GOALS:
                    s = match(args, tmp, team, n, in_process, args.config)
                    key = f"{mode}_{team.split(':')[0]}"
                    row[key] = {**s, "exchanges_per_s": n * FRAMES_PER_S * s["rtf"]}
                    if in_process and team == "cpp:Team":
                        row["physics_rtf"] = s["physics_rtf"]
                    cells += f" {s['rtf']:7.1f} {s['cpu_rtf']:7.1f} {row[key]['exchanges_per_s']:8.0f}"
            cap = f"{row['lcm_cap_rtf']:8.1f}" if caps else f"{'-':>8}"
            print(f"{n:>6} {cap} {row['physics_rtf']:8.1f}{cells}", flush=True)
            figures["table"].append(row)
        if args.json:
            args.json.write_text(json.dumps(figures, indent=2) + "\n")
            print(f"wrote {args.json}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
