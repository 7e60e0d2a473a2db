#!/usr/bin/env python3
"""Plays seeded matches and tabulates them (issue 5's measurements):

  supporters: the supporter team (py:Team) against a team of four strikers (py:Striker)
  ports:      the Python team (py:Team) against its C++ port (cpp:Team)

For each match: goals for and against, penalties by kind, ball possession share, and the
seconds robots spent stuck (spinning on the spot, or pressed against the boundary, for
more than 10 s while the game was PLAYING). Results print as tables and go to --out.
"""
from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
from collections import Counter, defaultdict
from pathlib import Path

from touchline_version import add_version_option

ROOT = Path(__file__).resolve().parents[1]
EXPERIMENTS = {"supporters": ("py:Team", "py:Striker"), "ports": ("py:Team", "cpp:Team")}
SAMPLE_EVERY = 3                   # truth frames: 10 Hz is plenty for these statistics
SAMPLES_PER_S = 30 // SAMPLE_EVERY
STUCK_WINDOW = 10 * SAMPLES_PER_S  # samples
STUCK_MOVE_MM = 150                # net movement under this over the window...
SPIN_RAD = 2 * math.pi             # ...while turning more than a full turn: spinning
WALL_MARGIN_MM = 250               # ...or within this of the carpet's edge: against a wall
POSSESSION_MM = 300                # the nearest robot this close to the ball has it


def play(build: Path, team0: str, team1: str, seed: int, extra: list, workdir: Path) -> tuple[dict, Path]:
    summary = workdir / f"summary-{seed}.json"
    args = [sys.executable, str(ROOT / "tools" / "launch.py"), "--build-dir", str(build), "--team0", team0,
            "--team1", team1, "--seed", str(seed), "--json", str(summary), "--log-dir", str(workdir), "--no-progress",
            *extra]
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit(f"evaluate_teams: match seed {seed} failed: {result.stderr.strip().splitlines()[-1:]}")
    log = max(workdir.glob(f"*_seed{seed}.lcmlog"), key=lambda p: p.stat().st_mtime)  # this match's
    return json.loads(summary.read_text()), log


def analyse_log(log: Path) -> dict:
    """Possession frames per team and stuck seconds per team, from the truth stream, on the
    field of the match's own TL_MATCH (the first message of its log)."""
    import lcm
    from touchline import game_state_t, match_config_t, world_truth_t

    playing = False
    possession = Counter()
    history = defaultdict(list)  # (team, player) -> [(x, y, theta, counts)]
    stuck_frames = Counter()
    edge_x = edge_y = None  # the carpet's edges, from TL_MATCH
    truth_frames = 0
    for event in lcm.EventLog(str(log), "r"):
        if event.channel == "TL_MATCH" and edge_x is None:
            match = match_config_t.decode(event.data)
            edge_x, edge_y = (size / 2 + match.border_mm for size in (match.field_length_mm, match.field_width_mm))
            continue
        if event.channel == "TL_GAME":
            playing = game_state_t.decode(event.data).state == game_state_t.PLAYING
            continue
        if event.channel != "TL_TRUTH":
            continue
        if edge_x is None:
            raise SystemExit(f"evaluate_teams: {log} has no TL_MATCH before its first TL_TRUTH")
        truth_frames += 1
        if truth_frames % SAMPLE_EVERY:
            continue
        truth = world_truth_t.decode(event.data)
        nearest = None
        for r in truth.robots:
            counts = playing and r.active and not r.penalised and not r.fallen
            h = history[(r.team, r.player)]
            h.append((r.body.x_mm, r.body.y_mm, r.body.theta_rad, counts))
            if counts and len(h) > STUCK_WINDOW and all(c for *_, c in h[-STUCK_WINDOW:]) and stuck(h, edge_x, edge_y):
                stuck_frames[r.team] += 1
            if len(h) > STUCK_WINDOW + 1:
                del h[0]
            d = math.hypot(r.body.x_mm - truth.ball_x_mm, r.body.y_mm - truth.ball_y_mm)
            if counts and d < POSSESSION_MM and (nearest is None or d < nearest[0]):
                nearest = (d, r.team)
        if nearest:
            possession[nearest[1]] += 1
    return {"possession_frames": [possession[0], possession[1]],
            "stuck_s": [stuck_frames[0] / SAMPLES_PER_S, stuck_frames[1] / SAMPLES_PER_S]}


def stuck(h: list, edge_x: float, edge_y: float) -> bool:
    window = h[-STUCK_WINDOW:]
    moved = math.hypot(window[-1][0] - window[0][0], window[-1][1] - window[0][1])
    if moved >= STUCK_MOVE_MM:
        return False
    turned = sum(abs(math.remainder(b[2] - a[2], 2 * math.pi)) for a, b in zip(window, window[1:]))
    at_wall = min(min(edge_x - abs(x), edge_y - abs(y)) for x, y, *_ in window) < WALL_MARGIN_MM
    return turned > SPIN_RAD or at_wall


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_version_option(parser, "tools/evaluate_teams.py")
    parser.add_argument("--matches", type=int, default=20)
    parser.add_argument("--experiments", nargs="+", choices=sorted(EXPERIMENTS), default=sorted(EXPERIMENTS))
    parser.add_argument("--build-dir", type=Path, default=ROOT / "build")
    parser.add_argument("--set", action="append", default=[], help="world config override for every match")
    parser.add_argument("--out", type=Path, default=Path("team_results.json"))
    args = parser.parse_args()
    sys.path.insert(0, str(args.build_dir / "lcm_types" / "gen" / "python"))
    extra = [a for item in args.set for a in ("--set", item)]
    results = {}
    for name in args.experiments:
        team0, team1 = EXPERIMENTS[name]
        rows = []
        for seed in range(1, args.matches + 1):
            with tempfile.TemporaryDirectory() as tmp:
                summary, log = play(args.build_dir, team0, team1, seed, extra, Path(tmp))
                rows.append({"seed": seed, "score": summary["score"],
                             "penalties": Counter(f"{p['team']}:{p['kind']}" for p in summary["penalties"]),
                             "falls": len(summary["falls"]), "sim_s": summary["sim_s"], **analyse_log(log)})
            r = rows[-1]
            print(f"{name} seed {seed:2d}: {r['score'][0]}:{r['score'][1]}, stuck {r['stuck_s']} s", flush=True)
        results[name] = {"team0": team0, "team1": team1, "matches": rows}
        report(name, team0, team1, rows)
    args.out.write_text(json.dumps(results, indent=2, default=dict) + "\n")
    print(f"evaluate_teams: results in {args.out}")
    return 0


def report(name: str, team0: str, team1: str, rows: list) -> None:
    n = len(rows)
    goals0 = sum(r["score"][0] for r in rows)
    goals1 = sum(r["score"][1] for r in rows)
    wins = sum(r["score"][0] > r["score"][1] for r in rows)
    losses = sum(r["score"][0] < r["score"][1] for r in rows)
    poss = [sum(r["possession_frames"][t] for r in rows) for t in (0, 1)]
    share = poss[0] / max(1, sum(poss))
    penalties = sum((r["penalties"] for r in rows), Counter())
    stuck = [sum(r["stuck_s"][t] for r in rows) for t in (0, 1)]
    print(f"\n{name}: team 0 = {team0}, team 1 = {team1}, {n} matches")
    print(f"  goals: team 0 {goals0} ({goals0 / n:.2f}/match), team 1 {goals1} ({goals1 / n:.2f}/match); "
          f"team 0 won {wins}, drew {n - wins - losses}, lost {losses}")
    print(f"  ball possession: team 0 {100 * share:.0f}%, team 1 {100 * (1 - share):.0f}%")
    for team in (0, 1):
        kinds = {k.split(":", 1)[1]: v for k, v in penalties.items() if k.startswith(f"{team}:")}
        print(f"  penalties team {team}: " + (", ".join(f"{k} {v}" for k, v in sorted(kinds.items())) or "none"))
    print(f"  falls: {sum(r['falls'] for r in rows)}; time stuck (>10 s spinning or at a wall): "
          f"team 0 {stuck[0]:.0f} s, team 1 {stuck[1]:.0f} s")


if __name__ == "__main__":
    sys.exit(main())
