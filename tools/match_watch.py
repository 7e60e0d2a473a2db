"""Follows a running match over LCM for the launcher: the match's own set-up and geometry
(TL_MATCH, which the launcher places the robots by), simulated time, real-time factor, score
and robot status, shown as progress (match_progress.py: a bar on a terminal, plain lines
elsewhere) and kept for the summary.

Anyone on the bus can publish on the channels watched here, so every message is decoded
with the generated types and checked before it is used; one that fails is counted per
channel and skipped. Anything else that goes wrong in the watching thread is kept in
`error` for the launcher to report: the thread never ends silently.
"""
from __future__ import annotations

import logging
import math
import select
import sys
import threading
import time
import traceback

CHANNELS = ("TL_MATCH", "TL_GAME", "TL_STATUS", "TL_EVENT")
MAX_TEAM_SIZE = 7  # players are numbered 1..7 (touchline/frame.hpp kMaxTeamSize)


class Malformed(Exception):
    """A message that decoded but says something impossible."""


def require(ok: bool, what: str) -> None:
    if not ok:
        raise Malformed(what)


class MatchWatch:
    def __init__(self, lcm_url: str, show_bar: bool = False, team_size: int = MAX_TEAM_SIZE, plan=None,
                 progress: str | None = None, console=None):
        """progress: 'bar', 'lines' or 'none' (show_bar: 'bar' or 'none'); plan: the match's
        planned length (match_checks.MatchPlan), else TL_MATCH's duration_s is the total."""
        import lcm
        from touchline import game_state_t, match_config_t, match_event_t, robot_status_t

        self._game_t, self._status_t, self._event_t = game_state_t, robot_status_t, match_event_t
        self._match_t = match_config_t
        self._team_size = team_size
        self.bus = lcm.LCM(lcm_url)
        self.bus.subscribe("TL_MATCH", self._on_match)
        self.bus.subscribe("TL_GAME", self._on_game)
        self.bus.subscribe("TL_STATUS", self._on_status)
        self.bus.subscribe("TL_EVENT", self._on_event)
        self.sim_s = 0.0         # the latest simulated time any message carried
        self.score = (0, 0)
        self.kicked_off = False  # the world published the game: every robot joined
        self.status: dict = {}   # (team, player) -> last robot_status_t
        self.events: list = []   # (sim_s, line) for robot trouble worth a summary line
        self._goals_counted = 0  # goals the progress total has grown by
        self.malformed = {channel: 0 for channel in CHANNELS}  # messages skipped, per channel
        self.last_malformed = ""  # why the latest one was skipped
        self.error: str | None = None  # why the watching thread stopped, if it failed
        self.state = "INITIAL"
        self.match = None  # the first valid match_config_t: the match as the world plays it
        self._start = time.monotonic()
        self._stop = threading.Event()
        self._progress_kind = progress or ("bar" if show_bar else "none")
        self._plan, self._console = plan, console
        self.progress = None  # a MatchProgress, made when TL_MATCH says how long the match may last
        self._thread = threading.Thread(target=self._run, name="match watch", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        try:
            fd = self.bus.fileno()
            while not self._stop.is_set():
                if select.select([fd], [], [], 0.1)[0]:
                    self.bus.handle()
        except BaseException as e:  # kept for the launcher, which stops the match and says why
            self.error = "".join(traceback.format_exception_only(type(e), e)).strip()

    def _decode(self, channel: str, data: bytes, msg_type, check):
        """The decoded message, or None (counted) if it does not decode or fails `check`."""
        try:
            msg = msg_type.decode(data)
            check(msg)
            return msg
        except Exception as e:  # any decoding failure of a forged or damaged message
            self.malformed[channel] += 1
            self.last_malformed = f"{channel}: {type(e).__name__}: {e}"
            return None

    def _check_robot(self, team: int, player: int) -> None:
        require(team in (0, 1), f"team {team}")
        require(1 <= player <= self._team_size, f"player {player}")

    def _check_game(self, msg) -> None:
        require(msg.utime >= 0, f"utime {msg.utime}")
        require(msg.INITIAL <= msg.state <= msg.STANDBY, f"state {msg.state}")
        require(msg.SET_PLAY_NONE <= msg.set_play <= msg.SET_PLAY_PENALTY_KICK, f"set play {msg.set_play}")
        require(msg.set_play == msg.SET_PLAY_NONE or msg.set_play_team in (0, 1), f"set play team {msg.set_play_team}")
        require(all(goals >= 0 for goals in msg.score), f"score {tuple(msg.score)}")
        require(msg.kickoff_team in (0, 1) and msg.first_half in (0, 1) and msg.secs_remaining >= 0,
                "kick-off team, half or clock out of range")

    def _check_status(self, msg) -> None:
        require(msg.utime >= 0, f"utime {msg.utime}")
        self._check_robot(msg.team, msg.player)
        require(msg.JOINED <= msg.state <= msg.REJECTED, f"state {msg.state}")
        require(msg.frames_answered >= 0 and msg.frames_missed >= 0, "negative frame counts")

    def _check_event(self, msg) -> None:
        require(msg.utime >= 0, f"utime {msg.utime}")
        require(msg.STATE_CHANGE <= msg.kind <= msg.GAME_STUCK, f"kind {msg.kind}")
        require(msg.team in (-1, 0, 1), f"team {msg.team}")
        require(0 <= msg.player <= self._team_size, f"player {msg.player}")

    def _check_match(self, msg) -> None:
        require(msg.types_version == msg.TYPES_VERSION,
                f"LCM types version {msg.types_version}, the launcher's is {msg.TYPES_VERSION}")
        require(1 <= msg.team_size <= MAX_TEAM_SIZE, f"team size {msg.team_size}")
        sizes = (msg.field_length_mm, msg.field_width_mm, msg.duration_s)
        require(all(math.isfinite(v) and v > 0 for v in sizes), "a field size or duration that is not positive")

    def _advance(self, utime: int) -> None:
        self.sim_s = max(self.sim_s, utime / 1e6)

    def _on_match(self, channel: str, data: bytes) -> None:
        msg = self._decode(channel, data, self._match_t, self._check_match)
        if msg is None or self.match is not None:  # the world repeats it unchanged
            return
        self._team_size = msg.team_size
        if self._progress_kind != "none":
            from match_progress import MatchProgress
            plan = self._plan
            self.progress = MatchProgress(self._progress_kind, plan.planned_s if plan else msg.duration_s,
                                          plan.goal_stoppage_s if plan else 0.0, msg.duration_s, self._console)
        self.match = msg  # last: the launcher reads it from another thread

    def _on_game(self, channel: str, data: bytes) -> None:
        msg = self._decode(channel, data, self._game_t, self._check_game)
        if msg is None:
            return
        self._advance(msg.utime)
        self.kicked_off = True
        self.score = tuple(msg.score)
        # Goals from the score, which every TL_GAME repeats, not from TL_EVENT's GOAL, which
        # the bus may drop: each adds READY and SET to the total.
        goals = sum(self.score)
        if self.progress is not None:
            for _ in range(goals - self._goals_counted):
                self.progress.goal()
            self.progress.update(self.sim_s, self.state, self.score)
        self._goals_counted = max(self._goals_counted, goals)

    def _on_status(self, channel: str, data: bytes) -> None:
        msg = self._decode(channel, data, self._status_t, self._check_status)
        if msg is None:
            return
        self._advance(msg.utime)
        before = self.status.get((msg.team, msg.player))
        self.status[(msg.team, msg.player)] = msg
        changed = before is None or before.state != msg.state  # not the world's repeats of a state
        if changed and msg.state in (msg.TIMED_OUT, msg.REJOINED, msg.REJECTED) and msg.detail:
            self.events.append((msg.utime / 1e6, f"team {msg.team} player {msg.player} {msg.detail}"))

    def _on_event(self, channel: str, data: bytes) -> None:
        msg = self._decode(channel, data, self._event_t, self._check_event)
        if msg is None:
            return
        self._advance(msg.utime)
        if msg.kind == msg.STATE_CHANGE:
            self.state = msg.text
        if msg.kind == msg.GAME_STUCK and self.progress is not None:
            self.progress.goal()  # READY and SET again, as after a goal

    def timed_out(self, team: int, player: int) -> bool:
        """Whether the world last said this robot is inactive (timed out), so that a
        restarted shim may take it over."""
        msg = self.status.get((team, player))
        return msg is not None and msg.state == msg.TIMED_OUT

    def say(self, line: str, file=None) -> None:
        """A line of the launcher's during the match (above the progress bar, if there is one):
        a warning for stderr, else information (--quiet and --log-level govern both)."""
        logger = logging.getLogger("launch")
        logger.warning(line) if file is sys.stderr else logger.info(line)

    def malformed_total(self) -> int:
        return sum(self.malformed.values())

    def real_time_factor(self) -> float:
        return self.sim_s / max(1e-9, time.monotonic() - self._start)

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(timeout=2)
        if self.progress is not None:
            self.progress.close()
