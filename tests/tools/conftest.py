"""Helpers for the launcher's tests: the launcher running in the background, the process
tree under it, and a listener for the world's robot status on the bus.

The launcher tests run inside a private network namespace (tools/netns, which ctest uses),
so the bus seen here is the match's own.
"""
from __future__ import annotations

import os
import queue
import select
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
LAUNCH = [sys.executable, str(ROOT / "tools" / "launch.py"), "--build-dir", str(BUILD)]
LCM_URL = "udpm://239.255.76.67:7667?ttl=0"
WAIT_S = 60  # the longest any step of a test waits before failing


@pytest.fixture(autouse=True)
def no_launcher_left_behind():
    """A test that fails half-way leaves no launcher (nor anything under it) running."""
    yield
    for launch in Launch.started:
        if launch.popen.poll() is None:
            launch.tree()
            launch.popen.terminate()
            try:
                launch.popen.wait(timeout=10)
            except subprocess.TimeoutExpired:
                launch.popen.kill()
                launch.popen.wait()
        for pid in wait_until_gone(sorted(launch.seen), timeout=10):
            os.kill(pid, signal.SIGKILL)
    Launch.started.clear()


class Launch:
    """tools/launch.py in the background, in a session of its own (as a terminal would run
    tools/match); its output lines are collected as they come. `own_netns` makes it enter
    a namespace of its own as tools/match does, instead of playing on this one's bus."""

    started: list = []  # every launcher a test started, for no_launcher_left_behind

    def __init__(self, *args, own_netns: bool = False):
        env = dict(os.environ)
        if own_netns:
            env.pop("TOUCHLINE_IN_NETNS", None)
        self.popen = subprocess.Popen([*LAUNCH, *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                      text=True, env=env, start_new_session=True)
        self.pid = self.popen.pid
        self.seen: set[int] = set()  # every process seen under it
        Launch.started.append(self)
        self.stdout: list[str] = []
        self.stderr: list[str] = []
        self._lines: "queue.Queue[str]" = queue.Queue()
        self._readers = [threading.Thread(target=self._read, args=(self.popen.stdout, self.stdout), daemon=True),
                         threading.Thread(target=self._read, args=(self.popen.stderr, self.stderr), daemon=True)]
        for reader in self._readers:
            reader.start()

    def _read(self, stream, lines: list) -> None:
        for line in stream:
            lines.append(line.rstrip("\n"))
            self._lines.put(line.rstrip("\n"))

    def wait_for_line(self, needle: str, timeout: float = WAIT_S) -> str:
        """Blocks until the launcher prints a line containing `needle` (an event, not a guess at time)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                line = self._lines.get(timeout=0.1)
            except queue.Empty:
                if self.popen.poll() is not None and self._lines.empty():
                    break
                continue
            if needle in line:
                return line
        raise AssertionError(f"the launcher never printed {needle!r}:\n" + self.output())

    def wait(self, timeout: float = WAIT_S) -> int:
        try:
            self.popen.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(self.pid, 9)
            self.popen.wait()
            raise AssertionError(f"the launcher did not exit within {timeout} s:\n" + self.output())
        for reader in self._readers:
            reader.join(timeout=5)
        return self.popen.returncode

    def output(self) -> str:
        return "\n".join(self.stdout + self.stderr)

    def tree(self) -> list[int]:
        """Every living process under the launcher."""
        processes = descendants(self.pid)
        self.seen.update(processes)
        return processes

    def child(self, needle: str) -> int:
        """The pid of the launcher's child whose command line contains `needle`."""
        processes = self.tree()
        matches = [pid for pid in processes if needle in cmdline(pid)]
        assert len(matches) == 1, f"{needle!r} among {[cmdline(p) for p in processes]}"
        return matches[0]

    def shim(self, team: int, player: int) -> int:
        return self.child(f"--team {team} --player {player} ")


def stat(pid: int) -> list[str] | None:
    """/proc/PID/stat's fields after the command name (state, ppid, pgrp, session, ...), or
    None if the process is gone."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    return text[text.rindex(")") + 2:].split()


def alive(pid: int) -> bool:
    fields = stat(pid)
    return fields is not None and fields[0] not in ("Z", "X")  # a zombie has ended


def cmdline(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
    except (FileNotFoundError, ProcessLookupError):
        return ""


def descendants(pid: int) -> list[int]:
    """Every living process under `pid`, children first."""
    parents = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and (fields := stat(int(entry.name))) and fields[0] not in ("Z", "X"):
            parents[int(entry.name)] = int(fields[1])
    found, frontier = [], [pid]
    while frontier:
        children = [p for p, ppid in parents.items() if ppid in frontier]
        found += children
        frontier = children
    return found


def wait_until_gone(pids: list[int], timeout: float = WAIT_S) -> list[int]:
    """The pids still alive after waiting up to `timeout` for all to end."""
    deadline = time.monotonic() + timeout
    while any(alive(p) for p in pids) and time.monotonic() < deadline:
        time.sleep(0.05)  # polling /proc for an exit, not hiding a race
    return [p for p in pids if alive(p)]


class StatusListener:
    """The world's robot_status_t messages (TL_STATUS), as they come."""

    def __init__(self):
        import lcm
        from touchline import robot_status_t

        self.type = robot_status_t
        self.bus = lcm.LCM(LCM_URL)
        self.messages: list = []
        self._new = threading.Condition()
        self._stop = threading.Event()
        self.bus.subscribe("TL_STATUS", self._on_status)
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _on_status(self, channel: str, data: bytes) -> None:
        with self._new:
            self.messages.append(self.type.decode(data))
            self._new.notify_all()

    def _run(self) -> None:
        fd = self.bus.fileno()
        while not self._stop.is_set():
            if select.select([fd], [], [], 0.05)[0]:
                self.bus.handle()

    def wait_for(self, team: int, player: int, state: int, timeout: float = WAIT_S) -> None:
        def seen() -> bool:
            return any(m.team == team and m.player == player and m.state == state for m in self.messages)
        with self._new:
            assert self._new.wait_for(seen, timeout), f"no status {state} for team {team} player {player}"

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(timeout=5)
