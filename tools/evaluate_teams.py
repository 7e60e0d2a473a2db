#!/usr/bin/env python3
"""Plays seeded matches and tabulates them (issue 5's measurements), as a sweep (sweep.py)
of two grid cells played side by side on every core:

  supporters:     the supporter team (py:Team) against a team of four strikers (py:Striker)
  supporters_cpp: the same in C++ (cpp:Team against cpp:Striker): the same decisions (the port
                  corpus), several times faster, so it affords more matches
  ports:          the Python team (py:Team) against its C++ port (cpp:Team)
  ports_swapped:  the same with the sides swapped (cpp:Team as team 0); with ports, the
                  results gain "ports_both_sides": Python's goal difference over both
                  arrangements, so the side a team plays on cancels out
  roles:          the supporters' tuned numbers (py:Team, supporters=tuned, the default) against
                  the thesis's own Algorithms 4.1 and 4.2 (py:Team,supporters=thesis)
  roles_cpp:      the same in C++
  supporters_thesis_cpp: the thesis's supporters (cpp:Team,supporters=thesis) against four
                  strikers (cpp:Striker), beside supporters_cpp

For each match: goals for and against, penalties by kind, ball possession share, and the
seconds robots spent stuck (spinning on the spot, or pressed against the boundary, for
more than 10 s while the game was PLAYING; match_stats.py). Results print as tables and go
to --out (per experiment its matches and the goal difference's 95 % interval); the sweep's
own table, summary and plot go to --sweep-out.
"""
from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path

import sweep
import sweep_grid
import sweep_summary
import touchline_paths
from touchline_version import add_version_option

EXPERIMENTS = {"supporters": ("py:Team", "py:Striker"), "supporters_cpp": ("cpp:Team", "cpp:Striker"),
               "ports": ("py:Team", "cpp:Team"), "ports_swapped": ("cpp:Team", "py:Team"),
               "roles": ("py:Team", "py:Team,supporters=thesis"),
               "roles_cpp": ("cpp:Team", "cpp:Team,supporters=thesis"),
               "supporters_thesis_cpp": ("cpp:Team,supporters=thesis", "cpp:Striker")}


def matches_of(experiments: list[str], matches: int, sets: list[str], launch: list[str],
               first_seed: int = 1) -> list[dict]:
    """The sweep's matches: each experiment a grid cell (cell i is experiments[i]), seeds
    first_seed .. first_seed + matches - 1."""
    found = []
    for cell, name in enumerate(experiments):
        team0, team1 = EXPERIMENTS[name]
        for match in sweep_grid.expand([team0], [team1], {}, [], list(range(first_seed, first_seed + matches)),
                                       [*(a for s in sets for a in ("--set", s)), *launch]):
            found.append({**match, "cell": cell})
    return found


def experiment_result(team0: str, team1: str, rows: list[dict]) -> dict:
    """One experiment in team_results.json's format: its matches seed by seed, and the goal
    difference's mean and 95 % interval (issue #17)."""
    played = sorted((r for r in rows if r["status"] in sweep_summary.PLAYED), key=lambda r: r["seed"])
    matches = [{"seed": r["seed"], "score": [r["goals0"], r["goals1"]],
                "penalties": json.loads(r["penalty_kinds"]), "falls": r["falls0"] + r["falls1"], "sim_s": r["sim_s"],
                "possession_frames": [r["possession_frames0"], r["possession_frames1"]],
                "stuck_s": [r["stuck_s0"], r["stuck_s1"]], "ball_moving_share": r["ball_moving_share"],
                "playing_share": r["playing_share"],
                "localisation_worst_mm": [r["localisation_worst_mm0"], r["localisation_worst_mm1"]]}
               for r in played]
    (cell,) = sweep_summary.summarise(played) if played else [{"goal_difference_mean": None,
                                                               "goal_difference_ci95": None}]
    return {"team0": team0, "team1": team1, "matches": matches,
            "goal_difference_mean": cell["goal_difference_mean"], "goal_difference_ci95": cell["goal_difference_ci95"],
            "per_match": per_match(matches)}


def both_sides(ports: dict, swapped: dict) -> dict:
    """Python's goal difference per match over the ports matches (Python team 0) and the
    ports_swapped ones (Python team 1, its difference negated): its mean and 95 % interval."""
    python_minus_cpp = ([m["score"][0] - m["score"][1] for m in ports["matches"]]
                        + [m["score"][1] - m["score"][0] for m in swapped["matches"]])
    interval = sweep_summary.ci95(python_minus_cpp)
    return {"matches": len(python_minus_cpp),
            "python_minus_cpp_mean": sum(python_minus_cpp) / len(python_minus_cpp) if python_minus_cpp else None,
            "python_minus_cpp_ci95": list(interval) if interval else None}


def per_match(matches: list[dict]) -> dict:
    """Issue #17's measures per match, for each team: pushing and illegal-defender penalties,
    the most stuck seconds of any match (0: no robot was ever stuck more than 10 s), the
    mean share of the match the ball was in play and moving, and that as a share of the time
    in PLAYING (set-up states, goals and half time are 35-45 % of a match; None without logs),
    and each team's worst robot's localisation RMS, mean over the matches and the largest."""
    n = max(1, len(matches))
    penalties = sum((Counter(m["penalties"]) for m in matches), Counter())
    moving = [m["ball_moving_share"] for m in matches if m["ball_moving_share"] != ""]
    playing = [m.get("playing_share", "") for m in matches if m["ball_moving_share"] != ""]
    stuck = [[m["stuck_s"][t] for m in matches if m["stuck_s"][t] != ""] for t in (0, 1)]
    worst = [[m["localisation_worst_mm"][t] for m in matches if m.get("localisation_worst_mm", ["", ""])[t] != ""]
             for t in (0, 1)]
    return {"pushing": [penalties[f"{t}:pushing"] / n for t in (0, 1)],
            "illegal_defender": [penalties[f"{t}:illegal defender"] / n for t in (0, 1)],
            "stuck_s_max": [max(s) if s else None for s in stuck],
            "ball_moving_share": sum(moving) / len(moving) if moving else None,
            "ball_moving_share_of_play": sum(moving) / sum(playing) if moving and "" not in playing else None,
            "localisation_worst_mm": [sum(w) / len(w) if w else None for w in worst],
            "localisation_worst_mm_max": [max(w) if w else None for w in worst]}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_version_option(parser, "tools/evaluate_teams.py")
    parser.add_argument("--matches", type=int, default=20)
    parser.add_argument("--first-seed", type=int, default=1,
                        help="the first match's seed (default 1): another range checks a result on matches it was "
                             "not tuned on")
    parser.add_argument("--experiments", nargs="+", choices=sorted(EXPERIMENTS), default=["ports", "supporters"])
    parser.add_argument("--build-dir", type=Path, default=touchline_paths.build_dir())
    parser.add_argument("--set", action="append", default=[], help="world config override for every match")
    parser.add_argument("--workers", type=int, default=sweep.CORES, help="matches at once (default: every core)")
    parser.add_argument("--out", type=Path, default=Path("team_results.json"))
    parser.add_argument("--sweep-out", type=Path, default=touchline_paths.work_dir("out") / "evaluate_teams",
                        help="the sweep's table, summary and plot (default out/evaluate_teams)")
    parser.add_argument("launch", nargs="*", help="after --: launcher options for every match (e.g. --in-process)")
    args = parser.parse_args()
    if args.matches < 1 or args.workers < 1 or args.first_seed < 1:
        parser.error("--matches, --workers and --first-seed must be at least 1")
    matches = matches_of(args.experiments, args.matches, args.set, args.launch, args.first_seed)
    try:
        sweep.check_launcher_options(matches)
        rows = sweep.sweep(matches, args.workers, args.build_dir, args.sweep_out, progress=sys.stderr.isatty())
    except sweep_grid.GridError as e:
        parser.exit(2, f"evaluate_teams: {e}\n")
    except KeyboardInterrupt:
        print(f"evaluate_teams: interrupted; the matches that finished are in {args.sweep_out}", file=sys.stderr)
        return 130
    if failed := [r for r in rows if r["status"] not in sweep_summary.PLAYED]:
        for r in failed:
            print(f"evaluate_teams: {r['label']} seed {r['seed']} failed: {r['error']}", file=sys.stderr)
        return 1
    results = {}
    for cell, name in enumerate(args.experiments):
        team0, team1 = EXPERIMENTS[name]
        results[name] = experiment_result(team0, team1, [r for r in rows if r["cell"] == cell])
        report(name, team0, team1, results[name])
    if "ports" in results and "ports_swapped" in results:
        results["ports_both_sides"] = both = both_sides(results["ports"], results["ports_swapped"])
        if both["python_minus_cpp_ci95"]:
            low, high = both["python_minus_cpp_ci95"]
            print(f"\nports_both_sides: Python minus C++ over {both['matches']} matches, both side arrangements: "
                  f"{both['python_minus_cpp_mean']:+.2f} goals a match, 95 % interval [{low:+.2f}, {high:+.2f}]")
    args.out.write_text(json.dumps(results, indent=2) + "\n")
    print(f"evaluate_teams: results in {args.out}, the sweep's table in {args.sweep_out}")
    return 0


def report(name: str, team0: str, team1: str, result: dict) -> None:
    rows = result["matches"]
    n = len(rows)
    goals0 = sum(r["score"][0] for r in rows)
    goals1 = sum(r["score"][1] for r in rows)
    wins = sum(r["score"][0] > r["score"][1] for r in rows)
    losses = sum(r["score"][0] < r["score"][1] for r in rows)
    poss = [sum(r["possession_frames"][t] or 0 for r in rows) for t in (0, 1)]
    share = poss[0] / max(1, sum(poss))
    penalties = sum((Counter(r["penalties"]) for r in rows), Counter())
    stuck = [sum(r["stuck_s"][t] or 0 for r in rows) for t in (0, 1)]
    ci = result["goal_difference_ci95"]
    print(f"\n{name}: team 0 = {team0}, team 1 = {team1}, {n} matches")
    print(f"  goals: team 0 {goals0} ({goals0 / n:.2f}/match), team 1 {goals1} ({goals1 / n:.2f}/match); "
          f"team 0 won {wins}, drew {n - wins - losses}, lost {losses}")
    if ci:
        print(f"  goal difference per match: {result['goal_difference_mean']:+.2f}, 95 % interval "
              f"[{ci[0]:+.2f}, {ci[1]:+.2f}]")
    if sum(poss):
        print(f"  ball possession: team 0 {100 * share:.0f}%, team 1 {100 * (1 - share):.0f}%")
    else:
        print("  ball possession: no robot had the ball")
    for team in (0, 1):
        kinds = {k.split(":", 1)[1]: v for k, v in penalties.items() if k.startswith(f"{team}:")}
        print(f"  penalties team {team}: " + (", ".join(f"{k} {v}" for k, v in sorted(kinds.items())) or "none"))
    print(f"  falls: {sum(r['falls'] for r in rows)}; time stuck (>10 s spinning or at a wall): "
          f"team 0 {stuck[0]:.0f} s, team 1 {stuck[1]:.0f} s")
    each = result["per_match"]
    print(f"  per match: pushing {each['pushing'][0]:.1f} v {each['pushing'][1]:.1f}, illegal defender "
          f"{each['illegal_defender'][0]:.1f} v {each['illegal_defender'][1]:.1f}"
          + (f", ball in play and moving {100 * each['ball_moving_share']:.0f} % of the match"
             if each["ball_moving_share"] is not None else "")
          + (f" ({100 * each['ball_moving_share_of_play']:.0f} % of the time in PLAYING)"
             if each["ball_moving_share_of_play"] is not None else ""))
    if None not in each["localisation_worst_mm"]:
        print(f"  localisation, worst robot per match: team 0 {each['localisation_worst_mm'][0]:.0f} mm "
              f"(largest {each['localisation_worst_mm_max'][0]:.0f}), team 1 {each['localisation_worst_mm'][1]:.0f} mm "
              f"(largest {each['localisation_worst_mm_max'][1]:.0f})")


if __name__ == "__main__":
    sys.exit(main())
