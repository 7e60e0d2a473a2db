#!/usr/bin/env python3
"""Records the port-regression corpus: real matches of the Python behaviour, every frame's
Blackboard snapshot (the Blackboard as the behaviour saw it and the request it returned),
into one LCM event log, tests/data/port_corpus.lcmlog by default.

Each scenario is a short match in a private network namespace: sim_world records every
message (--log) and the robots run the Python behaviour with --snapshot-every 1; the
snapshots of all scenarios are then gathered in scenario order. Rerun this after
changing what the Blackboard holds or what the skills read, then rerun the tests.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LCM_URL = "udpm://239.255.76.67:7667?ttl=0"

# (skill parameters for every robot, ball start, seconds). Robots start on their touchlines.
SCENARIOS = [
    ({"skill": "GoToBall"}, (0, 0), 12),
    ({"skill": "GoToBall"}, (-1200, 900), 12),
    ({"skill": "LineUpAndKick"}, (600, -500), 15),
    ({"skill": "LineUpAndKick", "dribble": "1"}, (-400, 300), 15),
    ({"skill": "GoToPose", "x": "-1500", "y": "300", "theta": "0.7"}, (0, 0), 10),
    ({"skill": "GoToPose", "x": "500", "y": "-800", "theta": "-2.5", "face_ball": "1"}, (1000, 1000), 10),
    ({"skill": "TrackBall"}, (-800, -600), 6),
    ({"skill": "HeadScan"}, (2500, 1500), 6),
]
ROBOTS = [(0, 1), (0, 3), (1, 2)]


def run_scenario(build: Path, params: dict, ball: tuple, seconds: float, log: Path) -> None:
    world = subprocess.Popen([build / "sim" / "sim_world", "--robots", str(len(ROBOTS)), "--duration", str(seconds),
                              "--quiet", "--lcm-url", LCM_URL, "--log", log,
                              "--set", f"match.ball_start_x_mm={ball[0]}", "--set", f"match.ball_start_y_mm={ball[1]}"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    shims = []
    for team, player in ROBOTS:
        args = [build / "robot_shim" / "robot_shim", "--team", str(team), "--player", str(player), "--behaviour", "py",
                "--lcm-url", LCM_URL, "--snapshot-every", "1"]
        for key, value in params.items():
            args += ["--param", f"{key}={value}"]
        shims.append(subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True))
    for name, proc in [("sim_world", world)] + [(f"robot_shim {t}/{p}", s) for (t, p), s in zip(ROBOTS, shims)]:
        _, err = proc.communicate(timeout=120)
        if proc.returncode != 0:
            raise SystemExit(f"record_corpus: {name} exited {proc.returncode}: {err.strip().splitlines()[-1:]}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", type=Path, default=ROOT / "build")
    parser.add_argument("--out", type=Path, default=ROOT / "tests" / "data" / "port_corpus.lcmlog")
    args = parser.parse_args()
    if os.environ.get("TOUCHLINE_IN_NETNS") != "1":
        return subprocess.call([str(ROOT / "tools" / "netns"), sys.executable, __file__, *sys.argv[1:]])
    import lcm

    count = 0
    with tempfile.TemporaryDirectory() as tmp:
        out = lcm.EventLog(str(args.out), "w", overwrite=True)
        for index, (params, ball, seconds) in enumerate(SCENARIOS):
            log = Path(tmp) / f"scenario{index}.lcmlog"
            run_scenario(args.build_dir, params, ball, seconds, log)
            for event in lcm.EventLog(str(log), "r"):
                if event.channel.startswith("TL_BLACKBOARD_"):
                    out.write_event(event.timestamp, event.channel, event.data)
                    count += 1
        out.close()
    print(f"record_corpus: {count} snapshots from {len(SCENARIOS)} scenarios in {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
