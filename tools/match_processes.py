"""The launcher's child processes (sim_world and the robot_shims): started each with a log
file and the match secret, described when they end, and stopped together.

Every child runs in a session of its own, so a Ctrl-C on the terminal reaches only the
launcher, which then stops the children in order; each also gets SIGTERM from the kernel
if the launcher dies (even by SIGKILL), so no child outlives it.
"""
from __future__ import annotations

import logging
import shutil
import signal
import subprocess
import time
from pathlib import Path

SECRET_ENV = "TOUCHLINE_MATCH_SECRET"  # how sim_world and robot_shim take the match secret
STOP_GRACE_S = 5  # wall seconds a child may take to exit after SIGTERM before SIGKILL


def describe_exit(rc: int) -> str:
    """'exited with code 2' or 'was killed by SIGKILL', for a Popen return code."""
    if rc < 0:
        try:
            return f"was killed by {signal.Signals(-rc).name}"
        except ValueError:
            return f"was killed by signal {-rc}"
    return f"exited with code {rc}"


class Child:
    def __init__(self, name: str, argv: list, log: Path, env: dict):
        self.name = name
        self.argv = [str(a) for a in argv]
        self.log = log
        with open(log, "w") as out:
            self.popen = subprocess.Popen(parent_death_prefix() + self.argv, stdout=out, stderr=out,
                                          env=env, start_new_session=True)

    @property
    def pid(self) -> int:
        return self.popen.pid

    def poll(self) -> int | None:
        return self.popen.poll()

    def last_line(self) -> str:
        lines = self.log.read_text(errors="replace").strip().splitlines()
        return lines[-1] if lines else "no output"

    def why(self) -> str:
        """How it ended: 'was killed by SIGKILL', or 'exited with code 2: ' and its last line."""
        rc = self.popen.returncode
        return describe_exit(rc) if rc < 0 else f"{describe_exit(rc)}: {self.last_line()}"

    def terminate(self) -> None:
        if self.popen.poll() is None:
            self.popen.send_signal(signal.SIGTERM)
            self.popen.send_signal(signal.SIGCONT)  # a stopped child handles SIGTERM at once


class Children:
    def __init__(self, logdir: Path, env: dict):
        self.logdir = logdir
        self.env = env
        self.all: list[Child] = []

    def start(self, name: str, argv: list, log_name: str | None = None) -> Child:
        log = self.logdir / ((log_name or name).replace(" ", "_").replace("/", "-") + ".log")
        child = Child(name, argv, log, self.env)
        logging.getLogger("launch").debug(f"launch: started {name} (pid {child.pid}, log {log}): "
                                          + " ".join(child.argv))
        self.all.append(child)
        return child

    def stop_all(self) -> None:
        for child in self.all:
            child.terminate()
        deadline = time.monotonic() + STOP_GRACE_S
        for child in self.all:
            try:
                child.popen.wait(timeout=max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                child.popen.kill()
                child.popen.wait()


def parent_death_prefix() -> list[str]:
    """setpriv (util-linux) sets the parent-death signal before it execs the child: Python's
    subprocess cannot, short of a preexec_fn, which is unsafe with the watcher's thread."""
    setpriv = shutil.which("setpriv")
    return [setpriv, "--pdeathsig", "TERM", "--"] if setpriv else []
