"""What the launcher does when a robot_shim dies during a match.

Before kick-off a dying shim is a broken set-up (a bad option or config): the match stops.
After kick-off the match goes on: the world marks the silent robot inactive after its
--robot-timeout-ms, and the keeper either leaves it so (the default: a restarted shim
starts its behaviour afresh, so the match is no longer the one the seed gives) or, with
restart on, starts the same shim again once the world reports the robot timed out (not
before: the world refuses a second shim for a robot it still counts active). A restarted
shim that dies before it takes the robot back is not restarted again, so a shim that
cannot start does not loop. Every death is kept for the summary: who, when, how.
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field

from match_processes import Child, Children


@dataclass
class Death:
    team: int
    player: int
    sim_s: float       # the simulated time the launcher noticed it (the match's latest)
    how: str           # 'was killed by SIGKILL', 'exited with code 1: <its last line>'
    outcome: str       # what came of it, for the summary
    restarted_sim_s: float | None = None  # when a new shim was started for the robot
    taken_back: bool = False  # the new shim took the robot back

    def line(self) -> str:
        return f"team {self.team} #{self.player}'s robot_shim {self.how}"


@dataclass
class Shim:
    team: int
    player: int
    argv: list
    child: Child
    restarts: int = 0
    waiting: bool = False   # dead, to be restarted once the world marks the robot inactive
    given_up: bool = False  # dead, not to be restarted: the robot stays inactive
    deaths: list = field(default_factory=list)

    @property
    def name(self) -> str:
        return f"robot_shim {self.team}/{self.player}"


class ShimKeeper:
    def __init__(self, children: Children, watch, restart: bool):
        self.children = children
        self.watch = watch
        self.restart = restart
        self.shims: list[Shim] = []
        self.deaths: list[Death] = []

    def start(self, team: int, player: int, argv: list) -> None:
        shim = Shim(team, player, argv, self.children.start(f"robot_shim {team}/{player}", argv))
        self.shims.append(shim)

    def check(self, kicked_off: bool) -> str | None:
        """Looks after the shims once; returns why the match must stop, or None. Before
        kick-off (every robot joined) a dead shim stops the match."""
        for shim in self.shims:
            if shim.given_up:
                continue
            if shim.waiting:
                if self.watch.timed_out(shim.team, shim.player):
                    self._restart(shim)
                continue
            self._note_taken_back(shim)
            if shim.child.poll() in (None, 0):  # 0: it heard the world's FINISHED, which the world
                continue                        # repeats for a while before it exits itself
            if not kicked_off:
                return f"{shim.name} {shim.child.why()} (logs in {self.children.logdir})"
            self._died(shim)
        return None

    def after_match(self, timeout_s: float, stopping) -> None:
        """Waits up to `timeout_s` for the shims to end after the world's FINISHED (or until
        `stopping()`). A restarted shim that had not taken its robot back is stopped; one that
        does not end cleanly counts as a death at the end of the match."""
        deadline = time.monotonic() + timeout_s
        for shim in self.shims:
            self._note_taken_back(shim)
            if shim.given_up or shim.waiting:
                continue
            if shim.restarts and not shim.deaths[-1].taken_back:
                shim.child.terminate()
                continue
            while shim.child.poll() is None and time.monotonic() < deadline and not stopping():
                time.sleep(0.1)  # polling an exit code, not hiding a race
            if stopping():
                return
            if shim.child.poll() is None:
                shim.child.terminate()
                self._record(shim, f"did not exit within {timeout_s:.0f} s of the end of the match",
                             "stopped it", "stopped after the match")
            elif shim.child.poll() != 0:
                self._record(shim, shim.child.why(), "after the end of the match", "after the end of the match")

    def _note_taken_back(self, shim: Shim) -> None:
        if shim.restarts and not shim.deaths[-1].taken_back and not self.watch.timed_out(shim.team, shim.player):
            death = shim.deaths[-1]
            death.taken_back = True  # the world counts the robot active again
            death.outcome = f"restarted at {death.restarted_sim_s:.1f} s; the new shim took the robot back"

    def _record(self, shim: Shim, how: str, then: str, outcome: str) -> Death:
        death = Death(shim.team, shim.player, self.watch.sim_s, how, outcome)
        shim.deaths.append(death)
        self.deaths.append(death)
        self.watch.say(f"launch: at {death.sim_s:.1f} s {death.line()}; {then}", file=sys.stderr)
        return death

    def _died(self, shim: Shim) -> None:
        failed_restart = shim.restarts and not shim.deaths[-1].taken_back
        if not self.restart:
            shim.given_up = True
            then = "the match goes on without it (--restart-dead restarts it)"
            outcome = "not restarted (no --restart-dead): the robot stayed inactive"
        elif failed_restart:
            before = shim.deaths[-1]
            before.outcome = f"restarted at {before.restarted_sim_s:.1f} s; the new shim died before it took the robot back"
            shim.given_up = True
            then = "it had not taken the robot back, so it is not restarted again"
            outcome = "not restarted again (it had not taken the robot back): the robot stayed inactive"
        else:
            shim.waiting = True
            then = "it is restarted once the world marks the robot inactive"
            outcome = "the match ended before the world marked the robot inactive, so it was not restarted"
        self._record(shim, shim.child.why(), then, outcome)

    def _restart(self, shim: Shim) -> None:
        shim.restarts += 1
        shim.waiting = False
        death = shim.deaths[-1]
        death.restarted_sim_s = self.watch.sim_s
        death.outcome = f"restarted at {death.restarted_sim_s:.1f} s; the match ended before the new shim took the robot back"
        shim.child = self.children.start(shim.name, shim.argv, f"{shim.name}.restart{shim.restarts}")
        self.watch.say(f"launch: at {self.watch.sim_s:.1f} s restarted {shim.name} (pid {shim.child.pid})",
                       file=sys.stderr)

    def summary(self) -> list[dict]:
        return [{"team": d.team, "player": d.player, "sim_s": d.sim_s, "how": d.how, "outcome": d.outcome,
                 "restarted_sim_s": d.restarted_sim_s, "taken_back": d.taken_back} for d in self.deaths]

    def lines(self) -> list[tuple[float, str]]:
        """(sim_s, line) for the summary's event list."""
        return [(d.sim_s, f"{d.line()}; {d.outcome}") for d in self.deaths]
