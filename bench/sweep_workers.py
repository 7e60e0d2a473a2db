"""Sweep scaling (bench/sweep_workers runs this): the same N seeded matches played with 1
worker and with more (default 1 and 2), each worker count --repeat times; prints the sweep's
wall time (min and median), the speed-up over one worker, and for 2 workers its ratio to
issue #14's goal (2 workers >= 1.8x one). The matches are the sweep's own (tools/sweep.py:
each launcher in a network namespace of its own, its log analysed); --ray ADDRESS measures
Ray tasks instead.

  bench/sweep_workers                          # 1 and 2 workers, 4 matches of 60 s, 2 v 2
  bench/sweep_workers --workers 1,4,8,16 --matches 32
"""
import argparse
import json
import os
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import sweep  # noqa: E402
import sweep_grid  # noqa: E402

GOAL_2_WORKERS = 1.8  # issue #14: two workers at least 1.8 times as fast as one


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--workers", default="1,2", help="worker counts, the first the baseline (default 1,2)")
    p.add_argument("--matches", type=int, default=4, help="matches per sweep (default 4)")
    p.add_argument("--duration", type=float, default=60, help="simulated seconds per match (default 60)")
    p.add_argument("--team-size", type=int, default=2, help="robots per team (default 2)")
    p.add_argument("--repeat", type=int, default=3, help="sweeps per worker count (default 3: min and median)")
    p.add_argument("--ray", metavar="ADDRESS", help="Ray tasks on this cluster ('local': a Ray instance here)")
    p.add_argument("--build-dir", type=Path, default=ROOT / "build")
    p.add_argument("--json", type=Path, help="also write the figures here")
    p.add_argument("launch", nargs="*", help="after --: more launcher options for every match (e.g. --in-process)")
    a = p.parse_args()
    try:
        counts = [int(w) for w in a.workers.split(",")]
    except ValueError:
        p.error(f"--workers must be like 1,2 or 1,4,8,16 (got '{a.workers}')")
    if a.matches < 1 or a.repeat < 1 or any(w < 1 for w in counts):
        p.error("--matches, --repeat and every worker count must be at least 1")
    matches = sweep_grid.expand([], [], {}, [], list(range(1, a.matches + 1)),
                                ["--team-size", str(a.team_size), "--duration", str(a.duration), *a.launch])
    sweep.check_launcher_options(matches)
    print(f"sweep_workers: {a.matches} matches, {a.team_size} v {a.team_size}, {a.duration:.0f} s simulated each, "
          f"{os.cpu_count()} cores here" + (f", Ray {a.ray}" if a.ray else ""), flush=True)
    figures = {}
    for workers in counts:
        walls = []
        for _ in range(a.repeat):
            start = time.perf_counter()
            if a.ray:
                rows = sweep.run_ray(matches, a.ray, workers, 1.0, a.build_dir, None, lambda row: None)
            else:
                rows = sweep.run_local(matches, workers, a.build_dir, None, lambda row: None)
            walls.append(time.perf_counter() - start)
            if failed := [r for r in rows if r["status"] != "ok"]:
                sys.exit(f"sweep_workers: seed {failed[0]['seed']} failed: {failed[0]['error']}")
        figures[workers] = {"min_s": min(walls), "median_s": statistics.median(walls),
                            "rtf_median": statistics.median(r["rtf"] for r in rows)}
        base = figures[counts[0]]
        speedup = base["median_s"] / figures[workers]["median_s"]
        figures[workers]["speedup_median"] = speedup
        figures[workers]["speedup_min"] = base["min_s"] / figures[workers]["min_s"]
        goal = f"  ({speedup / GOAL_2_WORKERS:.2f} of the {GOAL_2_WORKERS}x goal)" if workers == 2 else ""
        print(f"{workers:3d} workers: {figures[workers]['min_s']:7.2f} s min {figures[workers]['median_s']:7.2f} s "
              f"median  speed-up x{speedup:.2f} median, x{figures[workers]['speedup_min']:.2f} min{goal}", flush=True)
    if a.json:
        a.json.write_text(json.dumps({"matches": a.matches, "duration_s": a.duration, "team_size": a.team_size,
                                      "cores": os.cpu_count(), "workers": figures}, indent=2) + "\n")


if __name__ == "__main__":
    main()
