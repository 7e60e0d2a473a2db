"""The launcher's progress display: simulated time against the match's planned length.

The total is the match as planned (sim_world --check: two halves with their INITIAL,
READY, SET and the half-time break, capped at the match's duration_s), grown by the
READY and SET the referee plays again after each goal, so that a full match ends at 100 %.
The ETA divides the simulated seconds left by the real-time factor of the last
ETA_WINDOW_S of wall time (not of the whole run, which includes the robots joining).

On a terminal, a rich progress bar owns the bottom line: it takes stdout and stderr while
it runs, so the launcher's own lines print above it, and its columns have fixed widths.
Elsewhere (a log file, CI), one plain line every LINE_EVERY of the match, through the
launcher's logger ("launch"), so --quiet and --log-level govern them as any other line.
"""
from __future__ import annotations

import logging
import math
import time
from collections import deque

LINE_EVERY = 0.1   # a plain progress line each tenth of the match
ETA_WINDOW_S = 10  # wall seconds of history the ETA's real-time factor is measured over ...
MIN_RATE_SPAN_S = 0.5  # ... once it spans this much (a backlog of messages read in one burst spans none)
logger = logging.getLogger("launch")


def clock(seconds: float) -> str:
    """'1:05', '1:02:03', or '?' while unknown."""
    if not math.isfinite(seconds) or seconds < 0:
        return "?"
    s = int(round(seconds))
    return f"{s // 3600}:{s % 3600 // 60:02d}:{s % 60:02d}" if s >= 3600 else f"{s // 60}:{s % 60:02d}"


class MatchProgress:
    def __init__(self, kind: str, planned_s: float, goal_stoppage_s: float, duration_s: float, console=None):
        """kind: 'bar' or 'lines'. planned_s: the length with no goal; each goal adds
        goal_stoppage_s, up to duration_s."""
        self.kind = kind
        self.total = min(planned_s, duration_s)
        self._goal_stoppage_s, self._duration_s = goal_stoppage_s, duration_s
        self.sim_s = 0.0
        self.state, self.score = "INITIAL", (0, 0)
        self._samples: deque = deque()  # (wall, sim_s) of the last ETA_WINDOW_S
        self._next_line = LINE_EVERY
        self._bar = None
        if kind == "bar":
            self._start_bar(console)

    def _start_bar(self, console) -> None:
        from rich.console import Console
        from rich.progress import BarColumn, Progress, TextColumn
        from rich.table import Column

        def fixed(template: str, width: int, justify: str = "left") -> TextColumn:
            return TextColumn(template, justify=justify, table_column=Column(width=width, no_wrap=True))

        self._bar = Progress(
            fixed("{task.fields[state]}", 8), fixed("{task.fields[score]}", 5),
            BarColumn(bar_width=30), fixed("{task.percentage:>3.0f} %", 5, "right"),
            fixed("{task.fields[sim]}", 16, "right"), fixed("{task.fields[rtf]}", 8, "right"),
            fixed("{task.fields[eta]}", 13),
            console=console or Console(), redirect_stdout=True, redirect_stderr=True, refresh_per_second=4)
        self._task = self._bar.add_task("match", total=self.total, **self._fields())
        self._bar.start()

    def real_time_factor(self) -> float:
        """Simulated over wall seconds across the window: nan until it spans MIN_RATE_SPAN_S."""
        if len(self._samples) < 2:
            return math.nan
        (wall0, sim0), (wall1, sim1) = self._samples[0], self._samples[-1]
        return (sim1 - sim0) / (wall1 - wall0) if wall1 - wall0 >= MIN_RATE_SPAN_S else math.nan

    def eta_s(self) -> float:
        rtf = self.real_time_factor()
        return (self.total - self.sim_s) / rtf if rtf > 0 else math.nan

    def _fields(self) -> dict:
        rtf = self.real_time_factor()
        return {"state": self.state, "score": f"{self.score[0]}:{self.score[1]}",
                "sim": f"{self.sim_s:.0f}/{self.total:.0f} s sim",
                "rtf": f"x{rtf:.1f}" if math.isfinite(rtf) else "x?", "eta": f"ETA {clock(self.eta_s())}"}

    def goal(self) -> None:
        """A goal or a stuck game: READY and SET again before the kick-off."""
        self.total = min(self._duration_s, self.total + self._goal_stoppage_s)

    def update(self, sim_s: float, state: str, score: tuple, wall: float | None = None) -> None:
        wall = time.monotonic() if wall is None else wall
        self.sim_s, self.state, self.score = max(self.sim_s, sim_s), state, score
        self._samples.append((wall, self.sim_s))
        while len(self._samples) > 2 and wall - self._samples[0][0] > ETA_WINDOW_S:
            self._samples.popleft()
        if self._bar is not None:
            self._bar.update(self._task, completed=min(self.sim_s, self.total), total=self.total, **self._fields())
        elif self.kind == "lines" and self.total > 0 and self.sim_s >= self._next_line * self.total:
            while self._next_line * self.total <= self.sim_s:
                self._next_line += LINE_EVERY
            fields = self._fields()
            logger.info(f"launch: {min(100.0, 100 * self.sim_s / self.total):3.0f} % of the match, "
                        f"{self.sim_s:.0f} of {self.total:.0f} s simulated, {fields['rtf']} real time, {self.state}, "
                        f"score {fields['score']}, {fields['eta']}")

    def close(self) -> None:
        if self._bar is not None:
            self._bar.stop()
            self._bar = None
