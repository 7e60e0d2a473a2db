"""Trains the tile-coded Sarsa(lambda) go-to-pose policy over the whole field and writes
it as a policy file for the behaviours, with its learning curve and training figures.

  learning/train_tiles [--episodes N] [--seed S] [--policy PATH] [--out DIR]
"""
import argparse
import json
import math
import pathlib
import sys
import time

from tqdm import tqdm

from touchline_rl.evaluation import evaluate, fixed_starts, tile_q_runner
from touchline_rl.native import REPO, touchline_sim
from touchline_rl.plots import plot_curves
from touchline_rl.policy_file import write_policy
from touchline_rl.tile_training import TrainingDef, make_q, train

CHECK_STARTS = 50   # greedy evaluations during training (the full one is learning/evaluate)
CHECK_SEED = 7      # a start set apart from the evaluation's


def parse(argv):
    parser = argparse.ArgumentParser(prog="learning/train_tiles", description=__doc__.splitlines()[0])
    parser.add_argument("--version", action="version", version=f"learning/train_tiles {(REPO / 'VERSION').read_text().strip()}")
    parser.add_argument("--episodes", type=int, default=TrainingDef.episodes)
    parser.add_argument("--seed", type=int, default=TrainingDef.seed)
    parser.add_argument("--report-every", type=int, default=2000, help="episodes between curve points")
    parser.add_argument("--policy", type=pathlib.Path, default=REPO / "config" / "policies" / "go_to_pose.policy")
    parser.add_argument("--out", type=pathlib.Path, default=REPO / "docs" / "learning" / "tiles",
                        help="folder for training.json and curve.png")
    parser.add_argument("--no-progress", action="store_true")
    args = parser.parse_args(argv)
    if args.episodes < 1 or args.report_every < 1:
        parser.error("--episodes and --report-every must be at least 1")
    return args


def main(argv=None):
    args = parse(argv)
    definition = TrainingDef(episodes=args.episodes, seed=args.seed)
    sim = touchline_sim.SingleRobotSim()
    q = make_q(definition.coding)
    q.weights[:] = definition.initial_value / q.tilings
    checks = fixed_starts(CHECK_STARTS, sim.field, seed=CHECK_SEED)
    check = tile_q_runner(q, sim, definition.success_distance_mm, definition.success_heading_rad,
                          definition.max_frames)
    curve = []
    started = time.perf_counter()
    with tqdm(total=args.episodes, disable=args.no_progress, unit="ep", desc="Sarsa(lambda)") as bar:
        for episode, mean_frames, success in train(definition, q=q, sim=sim, progress=bar.update,
                                                   report_every=args.report_every):
            greedy, _ = evaluate(check, checks, sim.walk_limits)
            curve.append({"episode": episode, "training_mean_frames": mean_frames, "training_success": success,
                          "greedy_success": greedy["success_rate"],
                          "greedy_median_time_over_bound": greedy["median_time_over_bound"]})
            bar.set_postfix(greedy=f"{greedy['success_rate']:.0%}", ratio=f"{greedy['median_time_over_bound']:.2f}")
    wall_s = time.perf_counter() - started

    args.policy.parent.mkdir(parents=True, exist_ok=True)
    args.out.mkdir(parents=True, exist_ok=True)
    write_policy(args.policy, q, definition.success_distance_mm, definition.success_heading_rad,
                 comments=[f"learning/train_tiles --episodes {args.episodes} --seed {args.seed}",
                           f"trained in {wall_s:.0f} s; Sarsa(lambda) alpha {definition.alpha} "
                           f"lambda {definition.lambda_}, tile coding over the robot-relative target"])
    record = {"definition": vars(definition), "wall_s": wall_s, "curve": curve, "policy": str(args.policy)}
    (args.out / "training.json").write_text(json.dumps(record, indent=2, default=str))
    xs = [c["episode"] for c in curve]
    plot_curves(args.out / "curve.png", "Tile-coded Sarsa(lambda), go-to-pose over the whole field", "episodes", {
        "success rate": {"training (epsilon-greedy)": (xs, [c["training_success"] for c in curve]),
                         f"greedy, {CHECK_STARTS} fixed starts": (xs, [c["greedy_success"] for c in curve])},
        "median time / lower bound (greedy)": {
            "learned": (xs, [min(c["greedy_median_time_over_bound"], 5.0) for c in curve])},
    })
    print(f"trained {args.episodes} episodes in {wall_s:.0f} s; policy {args.policy}; curve {args.out / 'curve.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
