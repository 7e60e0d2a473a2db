"""Evaluates go-to-pose skills on the same fixed seeded starts over the whole field and
writes a table (issue 7): the learned policy as the learner runs it, the same policy
deployed in the C++ behaviour (LearnedGoToPose, reading the policy file), the hand-coded
GoToPose skill (thesis Algorithm 4.3 with forward-first).

  learning/evaluate [--policy PATH] [--starts 200] [--out DIR]
"""
import argparse
import json
import math
import pathlib
import sys
import time

from tqdm import tqdm

from touchline_rl.evaluation import behaviour_runner, evaluate, fixed_starts, tile_q_runner
from touchline_rl.native import REPO, touchline_sim
from touchline_rl.policy_file import read_policy

MAX_FRAMES = 1200  # 40 s


def parse(argv):
    parser = argparse.ArgumentParser(prog="learning/evaluate", description=__doc__.splitlines()[0])
    parser.add_argument("--version", action="version", version=f"learning/evaluate {(REPO / 'VERSION').read_text().strip()}")
    parser.add_argument("--policy", type=pathlib.Path, default=REPO / "config" / "policies" / "go_to_pose.policy")
    parser.add_argument("--starts", type=int, default=200)
    parser.add_argument("--out", type=pathlib.Path, default=REPO / "docs" / "learning" / "evaluation")
    parser.add_argument("--no-progress", action="store_true")
    args = parser.parse_args(argv)
    if args.starts < 1:
        parser.error("--starts must be at least 1")
    if not args.policy.is_file():
        parser.error(f"no policy file {args.policy} (train one with learning/train_tiles)")
    return args


def table(results):
    lines = ["| skill | success (50 mm, 10°) | median time / lower bound | median time (s) | wall (s) |",
             "|---|---|---|---|---|"]
    for name, r in results.items():
        lines.append(f"| {name} | {r['success_rate']:.1%} | {r['median_time_over_bound']:.3f} | "
                     f"{r['median_time_s']:.2f} | {r['wall_s']:.1f} |")
    return "\n".join(lines)


def main(argv=None):
    args = parse(argv)
    try:
        q, distance_mm, heading_rad = read_policy(args.policy)
    except (OSError, ValueError) as error:
        sys.exit(f"learning/evaluate: {error}")
    sim = touchline_sim.SingleRobotSim()
    starts = fixed_starts(args.starts, sim.field)
    policy_param = {"policy": str(args.policy.resolve())}
    skills = {
        "learned (TileQ greedy, in the learner)": tile_q_runner(q, sim, distance_mm, heading_rad, MAX_FRAMES),
        "learned, deployed (C++ LearnedGoToPose)": behaviour_runner(sim, "LearnedGoToPose", distance_mm,
                                                                    heading_rad, MAX_FRAMES, policy_param),
        "hand-coded (C++ GoToPose)": behaviour_runner(sim, "GoToPose", distance_mm, heading_rad, MAX_FRAMES),
    }
    results, rows = {}, {}
    for name, run in skills.items():
        started = time.perf_counter()
        with tqdm(total=len(starts), desc=name, disable=args.no_progress) as bar:
            results[name], rows[name] = evaluate(run, starts, sim.walk_limits, progress=bar.update)
        results[name]["wall_s"] = time.perf_counter() - started
    args.out.mkdir(parents=True, exist_ok=True)
    text = table(results)
    (args.out / "results.md").write_text(
        f"# Go-to-pose on {args.starts} fixed seeded starts\n\nPolicy: `{args.policy.relative_to(REPO) if args.policy.resolve().is_relative_to(REPO) else args.policy}`; "
        f"starts and targets uniform inside the field's lines, headings uniform; success: within "
        f"{distance_mm:.0f} mm and {math.degrees(heading_rad):.0f}° within {MAX_FRAMES // 30} s; "
        "a failure counts as infinitely slow in the median.\n\n" + text + "\n")
    (args.out / "results.json").write_text(json.dumps({"summary": results, "episodes": rows}, indent=1))
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
