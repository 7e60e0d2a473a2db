#!/usr/bin/env python3
"""Records the port-regression corpus: real matches of the Python behaviour, every frame's
Blackboard snapshot (the Blackboard as the behaviour saw it and the request it returned),
into one LCM event log, tests/data/port_corpus.lcmlog by default.

Each scenario is a short match in a private network namespace: sim_world records every
message (--log) and the robots run the Python behaviour with --snapshot-every 1; the
snapshots of all scenarios are then gathered in scenario order, each scenario's by simulated
time and then robot, stamped with simulated time and without the bus's tag: the same build
records the same bytes, so a re-recorded corpus differs only where what a behaviour saw or did
differs. Rerun this after changing what the Blackboard holds or what the skills read, then
rerun the tests.

The learned-walker scenarios (walker=learned, LearnedGoToPose) read the go-to-pose policy
from --data-dir (default config/, where the trained policy lives); --synthetic-policy
records them with tools/synthetic_policy.py's stand-in instead, from a temporary data
directory. test_port_regression replays them with whatever policy it is given: any policy
tests that both ports pick the same actions.
"""
from __future__ import annotations

import argparse
import os
import secrets
import subprocess
import sys
import tempfile
from pathlib import Path

import touchline_paths
from touchline_version import add_version_option

ROOT = Path(__file__).resolve().parents[1]
LCM_URL = "udpm://239.255.76.67:7667?ttl=0"

# (skill parameters for every robot, ball start, seconds, robots, world overrides). Robots
# start on their touchlines; the team scenarios shorten READY so PLAYING comes soon.
THREE = [(0, 1), (0, 3), (1, 2)]
FOUR_A_SIDE = [(t, p) for t in (0, 1) for p in range(1, 5)]
QUICK_KICKOFF = ["rules.ready_s=6", "rules.set_s=1"]
SCENARIOS = [
    ({"skill": "GoToBall"}, (0, 0), 12, THREE, []),
    ({"skill": "GoToBall"}, (-1200, 900), 12, THREE, []),
    ({"skill": "LineUpAndKick"}, (600, -500), 15, THREE, []),
    ({"skill": "LineUpAndKick", "dribble": "1"}, (-400, 300), 15, THREE, []),
    ({"skill": "GoToPose", "x": "-1500", "y": "300", "theta": "0.7"}, (0, 0), 10, THREE, []),
    ({"skill": "GoToPose", "x": "500", "y": "-800", "theta": "-2.5", "face_ball": "1"}, (1000, 1000), 10, THREE, []),
    ({"skill": "TrackBall"}, (-800, -600), 6, THREE, []),
    ({"skill": "HeadScan"}, (2500, 1500), 6, THREE, []),
    ({"skill": "Team"}, (0, 0), 24, FOUR_A_SIDE, QUICK_KICKOFF),
    ({"skill": "Team"}, (-1500, 1000), 24, FOUR_A_SIDE, QUICK_KICKOFF),
    ({"skill": "Team"}, (1000, 1990), 28, FOUR_A_SIDE, QUICK_KICKOFF),  # by the touchline: balls out, put back
    ({"skill": "Striker"}, (800, 400), 16, THREE, QUICK_KICKOFF),
    ({"skill": "Goalie"}, (-2200, 300), 16, THREE, QUICK_KICKOFF),
    ({"skill": "Midfielder"}, (1600, -700), 16, THREE, QUICK_KICKOFF),
    ({"skill": "Defender"}, (-1000, 500), 16, THREE, QUICK_KICKOFF),
    ({"skill": "Defender", "supporters": "thesis"}, (-1000, 500), 16, THREE, QUICK_KICKOFF),
    ({"skill": "LearnedGoToPose", "x": "-1500", "y": "300", "theta": "0.7"}, (0, 0), 10, THREE, []),
    ({"skill": "GoToBall", "walker": "learned"}, (-1200, 900), 12, THREE, []),
    ({"skill": "Striker", "walker": "learned"}, (800, 400), 16, THREE, QUICK_KICKOFF),
]
POLICY = Path("policies") / "go_to_pose.policy"  # what the learned scenarios read, data-relative


def run_scenario(build: Path, data_dir: Path, params: dict, ball: tuple, seconds: float, robots: list, sets: list,
                 log: Path) -> None:
    overrides = [f"match.ball_start_x_mm={ball[0]}", f"match.ball_start_y_mm={ball[1]}", *sets]
    os.environ.setdefault("TOUCHLINE_MATCH_SECRET", secrets.token_hex(32))  # the programs authenticate with it
    world = subprocess.Popen([build / "bin" / "sim_world", "--robots", str(len(robots)), "--duration", str(seconds),
                              "--quiet", "--lcm-url", LCM_URL, "--log", log,
                              *[a for o in overrides for a in ("--set", o)]],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    shims = []
    for team, player in robots:
        args = [build / "bin" / "robot_shim", "--team", str(team), "--player", str(player), "--behaviour", "py",
                "--lcm-url", LCM_URL, "--snapshot-every", "1", "--data-dir", data_dir]
        for key, value in params.items():
            args += ["--param", f"{key}={value}"]
        shims.append(subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True))
    for name, proc in [("sim_world", world)] + [(f"robot_shim {t}/{p}", s) for (t, p), s in zip(robots, shims)]:
        _, err = proc.communicate(timeout=120)
        if proc.returncode != 0:
            raise SystemExit(f"record_corpus: {name} exited {proc.returncode}: {err.strip().splitlines()[-1:]}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_version_option(parser, "tools/record_corpus.py")
    parser.add_argument("--build-dir", type=Path, default=ROOT / "build")
    parser.add_argument("--out", type=Path, default=ROOT / "tests" / "data" / "port_corpus.lcmlog")
    parser.add_argument("--data-dir", type=Path, default=ROOT / "config",
                        help="the robots' data directory, holding %s (default config/)" % POLICY)
    parser.add_argument("--synthetic-policy", action="store_true",
                        help="record the learned scenarios with tools/synthetic_policy.py's policy (from a "
                             "temporary data directory) instead of --data-dir's")
    args = parser.parse_args()
    if not args.synthetic_policy and not (args.data_dir / POLICY).is_file():
        parser.error(f"no policy at {args.data_dir / POLICY} for the learned scenarios "
                     "(train one, or record with --synthetic-policy)")
    if os.environ.get("TOUCHLINE_IN_NETNS") != "1":
        return subprocess.call([str(ROOT / "tools" / "netns"), sys.executable, __file__, *sys.argv[1:]])
    import lcm
    sys.path[:0] = touchline_paths.lcm_python_dirs(args.build_dir)
    from touchline import blackboard_snapshot_t

    count = 0
    with tempfile.TemporaryDirectory() as tmp:
        data_dir = args.data_dir
        if args.synthetic_policy:
            sys.path.insert(0, str(ROOT / "tools"))
            from synthetic_policy import write_policy

            data_dir = Path(tmp) / "data"
            write_policy(data_dir / POLICY)
        out = lcm.EventLog(str(args.out), "w", overwrite=True)
        for index, (params, ball, seconds, robots, sets) in enumerate(SCENARIOS):
            log = Path(tmp) / f"scenario{index}.lcmlog"
            run_scenario(args.build_dir, data_dir, params, ball, seconds, robots, sets, log)
            # Stamped with simulated time and sorted by it, then by robot, whatever order they
            # reached the recorder, and without the bus's tag (bus.hpp: keyed by this run's
            # secret): the same build records the same bytes.
            snapshots = sorted((snapshot.utime, event.channel, snapshot.encode())
                               for event in lcm.EventLog(str(log), "r") if event.channel.startswith("TL_BLACKBOARD_")
                               for snapshot in [blackboard_snapshot_t.decode(event.data)])
            for utime, channel, data in snapshots:
                out.write_event(utime, channel, data)
            count += len(snapshots)
        out.close()
    policy = "the synthetic policy" if args.synthetic_policy else data_dir / POLICY
    print(f"record_corpus: {count} snapshots from {len(SCENARIOS)} scenarios in {args.out} (learned walker: {policy})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
