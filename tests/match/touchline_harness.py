"""Starts sim_world and robot_shim processes for multi-process tests and watches them.

Every test here runs inside a private network namespace (tools/netns, which ctest uses),
so LCM multicast stays on this namespace's loopback and parallel tests never meet.
"""
from __future__ import annotations

import configparser
import hashlib
import hmac
import json
import os
import queue
import secrets
import subprocess
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
SIM_WORLD = BUILD / "bin" / "sim_world"
ROBOT_SHIM = BUILD / "bin" / "robot_shim"
WALK_INI = ROOT / "config" / "walk.ini"
LCM_URL = "udpm://239.255.76.67:7667?ttl=0"
# What robots send the world (answers, joins, Blackboards) goes to the port above; what they
# hear (sense, game, join replies) is copied to the port above that (bridge/lcm lanes.hpp).
UPLINK_URL = "udpm://239.255.76.67:7668?ttl=0"
ROBOTS_URL = "udpm://239.255.76.67:7669?ttl=0"
WAIT_S = 60  # the longest any step of a test waits before failing
# Every program of a match authenticates its messages with one secret; the children inherit it.
os.environ.setdefault("TOUCHLINE_MATCH_SECRET", secrets.token_hex(32))


def sealed(channel: str, payload: bytes, secret_hex: str | None = None) -> bytes:
    """`payload` with the tag the match bus requires (HMAC-SHA-256 over the channel, a zero
    byte and the payload), made with this match's secret unless another is given."""
    key = bytes.fromhex(secret_hex or os.environ["TOUCHLINE_MATCH_SECRET"])
    return payload + hmac.new(key, channel.encode() + b"\0" + payload, hashlib.sha256).digest()


class Proc:
    """A child process whose stderr lines are collected as they come."""

    def __init__(self, name: str, args: list[str]):
        self.name = name
        self.args = [str(a) for a in args]
        self.popen = subprocess.Popen(self.args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.lines: "queue.Queue[str]" = queue.Queue()
        self.stderr: list[str] = []
        self._stdout: list[str] = []
        self._readers = [threading.Thread(target=self._read_stderr, daemon=True),
                         threading.Thread(target=self._read_stdout, daemon=True)]
        for reader in self._readers:
            reader.start()

    def _read_stderr(self) -> None:
        for line in self.popen.stderr:
            self.stderr.append(line.rstrip("\n"))
            self.lines.put(line.rstrip("\n"))

    def _read_stdout(self) -> None:
        self._stdout.extend(self.popen.stdout)

    @property
    def stdout(self) -> str:
        return "".join(self._stdout)

    def wait_for_line(self, needle: str, timeout: float = WAIT_S) -> str:
        """Blocks until a stderr line contains `needle` (an event, not a guess at time)."""
        deadline = time.monotonic() + timeout
        for seen in list(self.stderr):
            if needle in seen:
                return seen
        while time.monotonic() < deadline:
            try:
                line = self.lines.get(timeout=0.1)
            except queue.Empty:
                if self.popen.poll() is not None and self.lines.empty():
                    break
                continue
            if needle in line:
                return line
        raise AssertionError(f"{self.name} never printed {needle!r}; stderr:\n" + "\n".join(self.stderr))

    def wait(self, timeout: float = WAIT_S) -> int:
        try:
            self.popen.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.popen.kill()
            self.popen.wait()
            raise AssertionError(f"{self.name} did not exit within {timeout} s")
        for reader in self._readers:
            reader.join(timeout=5)
        return self.popen.returncode

    def kill(self) -> None:
        if self.popen.poll() is None:
            self.popen.kill()


@dataclass
class Match:
    world: Proc
    robots: dict = field(default_factory=dict)
    summary_path: Path | None = None

    def finish(self, timeout: float = WAIT_S) -> dict:
        """Waits for every process; returns the world's JSON summary."""
        rc = self.world.wait(timeout)
        assert rc == 0, f"sim_world exited {rc}:\n" + "\n".join(self.world.stderr)
        for name, robot in self.robots.items():
            rrc = robot.wait(timeout)
            assert rrc == 0, f"{name} exited {rrc}:\n" + "\n".join(robot.stderr)
        return json.loads(self.summary_path.read_text())

    def kill_all(self) -> None:
        for p in [self.world, *self.robots.values()]:
            p.kill()


def start_world(tmp_path: Path, robots: int, duration: float, *extra: str) -> Match:
    summary = tmp_path / f"summary-{time.monotonic_ns()}.json"
    world = Proc("sim_world", [SIM_WORLD, "--robots", robots, "--duration", duration, "--quiet",
                               "--summary", summary, "--lcm-url", LCM_URL, *extra])
    return Match(world=world, summary_path=summary)


def start_robot(match: Match, team: int, player: int, behaviour: str = "stand", world_timeout_s: float = 20,
                **params) -> Proc:
    args = [ROBOT_SHIM, "--team", team, "--player", player, "--behaviour", behaviour,
            "--walk-config", WALK_INI, "--lcm-url", LCM_URL, "--world-timeout", world_timeout_s]
    for key, value in params.items():
        args += ["--param", f"{key}={value}"]
    proc = Proc(f"robot_shim {team}/{player}", args)
    match.robots[f"{team}/{player}/{len(match.robots)}"] = proc
    return proc


def walk_def() -> dict:
    """The walk's limits as config/walk.ini sets them."""
    ini = configparser.ConfigParser(inline_comment_prefixes=("#", ";"))
    ini.read(WALK_INI)
    return {k: float(v) for k, v in ini["walk"].items()}


def nominal_distance(speed: float, accel: float, seconds: float) -> float:
    """Distance covered from standing with a linear ramp up to `speed` at `accel`."""
    ramp = speed / accel
    return speed * (seconds - ramp / 2) if seconds > ramp else accel * seconds**2 / 2


def robot_entry(summary: dict, team: int, player: int) -> dict:
    return next(r for r in summary["robots"] if r["team"] == team and r["player"] == player)
