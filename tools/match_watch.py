"""Follows a running match over LCM for the launcher: simulated time, real-time factor,
score and robot status, shown as a progress bar (tqdm) and kept for the summary."""
from __future__ import annotations

import select
import threading
import time


class MatchWatch:
    def __init__(self, lcm_url: str, duration_s: float, show_bar: bool):
        import lcm
        from touchline import game_state_t, match_event_t, robot_status_t

        self._game_t, self._status_t, self._event_t = game_state_t, robot_status_t, match_event_t
        self.bus = lcm.LCM(lcm_url)
        self.bus.subscribe("TL_GAME", self._on_game)
        self.bus.subscribe("TL_STATUS", self._on_status)
        self.bus.subscribe("TL_EVENT", self._on_event)
        self.sim_s = 0.0
        self.score = (0, 0)
        self.status: dict = {}   # (team, player) -> last robot_status_t
        self.events: list = []   # (sim_s, line) for robot trouble worth a summary line
        self.match_events: list = []  # decoded match_event_t: goals, penalties, falls, states
        self.state = "INITIAL"
        self._start = time.monotonic()
        self._stop = threading.Event()
        self._bar = None
        if show_bar:
            from tqdm import tqdm
            self._bar = tqdm(total=round(duration_s), unit="sim s", dynamic_ncols=True, leave=True)
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        fd = self.bus.fileno()
        while not self._stop.is_set():
            if select.select([fd], [], [], 0.1)[0]:
                self.bus.handle()

    def _on_game(self, channel: str, data: bytes) -> None:
        msg = self._game_t.decode(data)
        self.sim_s = msg.utime / 1e6
        self.score = tuple(msg.score)
        if self._bar is not None:
            self._bar.n = min(self._bar.total, round(self.sim_s))
            self._bar.set_postfix_str(f"x{self.real_time_factor():.1f} {self.state} score {self.score[0]}:{self.score[1]}")

    def _on_status(self, channel: str, data: bytes) -> None:
        msg = self._status_t.decode(data)
        self.status[(msg.team, msg.player)] = msg
        if msg.state in (msg.TIMED_OUT, msg.REJOINED, msg.REJECTED) and msg.detail:
            self.events.append((msg.utime / 1e6, f"team {msg.team} player {msg.player} {msg.detail}"))

    def _on_event(self, channel: str, data: bytes) -> None:
        msg = self._event_t.decode(data)
        self.match_events.append(msg)
        if msg.kind == msg.STATE_CHANGE:
            self.state = msg.text

    def real_time_factor(self) -> float:
        return self.sim_s / max(1e-9, time.monotonic() - self._start)

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(timeout=2)
        if self._bar is not None:
            self._bar.close()
