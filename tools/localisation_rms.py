#!/usr/bin/env python3
"""Localisation error of seeded in-process matches (issue #17 item 3): plays each seed with the
launcher (tools/launch.py --in-process), reads each robot's localisation_rms_mm from its --json
summary (the world's own figure: the belief's position error against truth over the frames
the robot was on the field) and prints, per match, the mean robot's and the worst robot's RMS,
then their means over the matches. Writes only into a temporary folder it removes.

  tools/localisation_rms.py --seeds 6-15 --team0 cpp:Team --team1 cpp:Team --set physics.x=y
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import touchline_paths

LAUNCHER = Path(__file__).resolve().parent / "launch.py"


def seeds_of(text: str) -> list[int]:
    """'6-15' or '1,4,9' (or both, comma separated) as a list of seeds."""
    seeds = []
    for part in text.split(","):
        low, _, high = part.partition("-")
        seeds.extend(range(int(low), int(high or low) + 1))
    return seeds


def play(seed: int, args: argparse.Namespace) -> list[float]:
    """Every robot's localisation RMS (mm) in the match of `seed`."""
    with tempfile.TemporaryDirectory(prefix="touchline-loc-") as work:
        summary = Path(work) / "summary.json"
        command = [sys.executable, str(LAUNCHER), "--in-process", "--no-log", "--quiet", "--build-dir",
                   str(args.build_dir), "--seed", str(seed), "--team0", args.team0, "--team1", args.team1,
                   "--json", str(summary), *(a for s in args.set for a in ("--set", s)), *args.launch]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0 or not summary.exists():
            raise RuntimeError(f"seed {seed}: {(done.stderr.strip() or 'no summary').splitlines()[-1]}")
        return [r["localisation_rms_mm"] for r in json.loads(summary.read_text())["robots"]]


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--seeds", type=seeds_of, default=seeds_of("6-15"), help="e.g. 6-15 or 1,3,5 (default 6-15)")
    p.add_argument("--team0", default="cpp:Team")
    p.add_argument("--team1", default="cpp:Team")
    p.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                   help="override a world config value (repeatable)")
    p.add_argument("--workers", type=int, default=2, help="matches played side by side (default 2)")
    p.add_argument("--build-dir", type=Path, default=touchline_paths.build_dir())
    p.add_argument("launch", nargs="*", help="more launcher options, after --")
    args = p.parse_args(argv)
    try:
        with ThreadPoolExecutor(max_workers=max(1, args.workers)) as pool:
            results = list(pool.map(lambda s: play(s, args), args.seeds))
    except RuntimeError as e:
        print(f"localisation_rms: {e}", file=sys.stderr)
        return 1
    print(f"{'seed':>5}{'mean robot mm':>15}{'worst robot mm':>16}")
    means, worsts = [], []
    for seed, rms in zip(args.seeds, results):
        means.append(sum(rms) / len(rms))
        worsts.append(max(rms))
        print(f"{seed:>5}{means[-1]:>15.0f}{worsts[-1]:>16.0f}")
    n = len(results)
    print(f"{'all':>5}{sum(means) / n:>15.0f}{sum(worsts) / n:>16.0f}   (worst of all {max(worsts):.0f} mm)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
