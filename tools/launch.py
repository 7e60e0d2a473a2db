#!/usr/bin/env python3
"""Plays a headless Touchline match: starts sim_world and one robot_shim per robot, waits
for them, shuts everything down cleanly on Ctrl-C or when any process fails (naming which
and why), and prints what happened.

Until the behaviour runtime lands, every robot runs the C++ `goto` behaviour towards its
kick-off position, so robots walk on for a purpose.
"""
from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_BUILD = ROOT / "build"

# Kick-off positions (field frame, team 0 defending -x) as fractions of the half length
# and half width, and a heading: goalie, defender, two forwards, then more supporters.
FORMATION = [(-0.9, 0.0, 0.0), (-0.6, 0.0, 0.0), (-0.3, 0.4, 0.0), (-0.3, -0.4, 0.0),
             (-0.45, 0.7, 0.0), (-0.45, -0.7, 0.0), (-0.15, 0.0, 0.0)]


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--team-size", type=int, default=4, help="robots per team, 1..7 (default 4)")
    p.add_argument("--duration", type=float, default=120.0, help="simulated seconds (default 120)")
    p.add_argument("--config", type=Path, default=ROOT / "config" / "spl2011.ini", help="world config")
    p.add_argument("--walk-config", type=Path, default=ROOT / "config" / "walk.ini", help="walk config")
    p.add_argument("--mode", choices=["lockstep", "realtime", "free"], default="lockstep")
    p.add_argument("--speed", type=float, default=1.0, help="real-time multiple for realtime/free")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--build-dir", type=Path, default=DEFAULT_BUILD)
    p.add_argument("--lcm-url", default="udpm://239.255.76.67:7667?ttl=0")
    p.add_argument("--host-network", action="store_true",
                   help="use this machine's network instead of a private namespace (to watch in lcm-spy)")
    p.add_argument("--json", type=Path, help="also write the world's summary here")
    args = p.parse_args(argv)
    if not 1 <= args.team_size <= 7:
        p.error("--team-size must be 1..7")
    if args.duration <= 0:
        p.error("--duration must be > 0")
    return args


def kickoff_targets(team_size: int, half_length: float, half_width: float) -> list:
    targets = []
    for team in (0, 1):
        sign = -1 if team == 1 else 1  # team 1 mirrors team 0 through the centre
        for player in range(1, team_size + 1):
            fx, fy, theta = FORMATION[player - 1]
            x, y = sign * fx * half_length, sign * fy * half_width
            targets.append((team, player, x, y, theta if team == 0 else 3.14159265))
    return targets


def field_half_sizes(config: Path) -> tuple:
    import configparser
    ini = configparser.ConfigParser(inline_comment_prefixes=("#", ";"))
    ini.read(config)
    field = ini["field"] if "field" in ini else {}
    return float(field.get("length_mm", 6000)) / 2, float(field.get("width_mm", 4000)) / 2


class Launcher:
    def __init__(self, args: argparse.Namespace):
        self.args = args
        self.procs: list[tuple[str, subprocess.Popen, Path]] = []
        self.logdir = Path(tempfile.mkdtemp(prefix="touchline-"))

    def start(self, name: str, argv: list) -> None:
        log = self.logdir / (name.replace(" ", "_").replace("/", "-") + ".log")
        with open(log, "w") as out:
            proc = subprocess.Popen([str(a) for a in argv], stdout=out if name != "sim_world" else subprocess.PIPE,
                                    stderr=out, text=True, start_new_session=True)
        self.procs.append((name, proc, log))

    def stop_all(self) -> None:
        for _, proc, _ in self.procs:
            if proc.poll() is None:
                proc.send_signal(signal.SIGTERM)
        deadline = time.monotonic() + 5
        for _, proc, _ in self.procs:
            try:
                proc.wait(timeout=max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                proc.kill()

    def failure(self) -> str | None:
        for name, proc, log in self.procs:
            rc = proc.poll()
            if rc not in (None, 0):
                lines = log.read_text().strip().splitlines()
                why = lines[-1] if lines else "no output"
                return f"{name} exited with code {rc}: {why} (logs in {self.logdir})"
        return None

    def run(self) -> int:
        a = self.args
        bin_world = a.build_dir / "sim" / "sim_world"
        bin_shim = a.build_dir / "robot_shim" / "robot_shim"
        for b in (bin_world, bin_shim):
            if not b.exists():
                print(f"launch: {b} not found; build first (tools/setup)", file=sys.stderr)
                return 2
        summary_path = a.json or (self.logdir / "summary.json")
        targets = kickoff_targets(a.team_size, *field_half_sizes(a.config))
        self.start("sim_world", [bin_world, "--config", a.config, "--set", f"match.team_size={a.team_size}",
                                 "--duration", a.duration, "--mode", a.mode, "--speed", a.speed, "--seed", a.seed,
                                 "--lcm-url", a.lcm_url, "--summary", summary_path])
        for team, player, x, y, theta in targets:
            self.start(f"robot_shim {team}/{player}",
                       [bin_shim, "--team", team, "--player", player, "--walk-config", a.walk_config,
                        "--lcm-url", a.lcm_url, "--behaviour", "goto", "--param", f"x={x:.0f}",
                        "--param", f"y={y:.0f}", "--param", f"theta={theta:.3f}"])
        print(f"launch: {2 * a.team_size} robots, {a.duration:.0f} s simulated, {a.mode} mode, seed {a.seed}")
        world = self.procs[0][1]
        try:
            while world.poll() is None:
                why = self.failure()
                if why:
                    print(f"launch: stopping the match: {why}", file=sys.stderr)
                    self.stop_all()
                    return 1
                time.sleep(0.1)  # polling child exit codes, not hiding a race
        except KeyboardInterrupt:
            print("launch: interrupted, stopping every process", file=sys.stderr)
            self.stop_all()
            return 130
        out = world.stdout.read()
        why = self.failure()
        self.stop_all()
        if why:
            print(f"launch: {why}", file=sys.stderr)
            return 1
        print(out, end="")
        self.report(json.loads(Path(summary_path).read_text()), targets)
        return 0

    @staticmethod
    def report(summary: dict, targets: list) -> None:
        print("  where each robot ended, against its kick-off position:")
        for team, player, x, y, _ in targets:
            r = next((r for r in summary["robots"] if r["team"] == team and r["player"] == player), None)
            if r is None:
                print(f"    team {team} player {player}: never joined")
                continue
            err = ((r["x_mm"] - x) ** 2 + (r["y_mm"] - y) ** 2) ** 0.5
            print(f"    team {team} player {player}: target ({x:6.0f}, {y:6.0f}) mm, off by {err:5.0f} mm")


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    if not args.host_network and os.environ.get("TOUCHLINE_IN_NETNS") != "1":
        netns = ROOT / "tools" / "netns"
        return subprocess.call([str(netns), sys.executable, __file__, *argv])
    return Launcher(args).run()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
