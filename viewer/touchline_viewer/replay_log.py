"""An lcm-logger log loaded for replay: the match's geometry (its first TL_MATCH), its truth
frames (each with its frame's sonar), game states, robot statuses and match events, indexed by
simulated time."""
from bisect import bisect_right
from pathlib import Path

import lcm

from .decode import EVENT, GAME, RECENT_EVENTS, SENSE, STATUS, TRUTH, decode
from .errors import ViewerError
from .field import MATCH, missing_match_reason

LCM_LOG_MAGIC = b"\xed\xa1\xda\x01"  # first bytes of every lcm-logger event


class ReplayLog:
    """Read-only after loading; shared by every replay connection."""

    def __init__(self, name: str, match: dict, truths: list, games: list, statuses: list, senses=(), events=()):
        if not truths:
            raise ViewerError(f"log {name} has no {TRUTH} messages to show")
        self.name = name
        self.match = match  # the page's geometry: field, ball, feet, camera, sonar
        self.truths = sorted(truths, key=lambda m: m["utime"])
        self.utimes = [m["utime"] for m in self.truths]
        self.games = sorted(games, key=lambda m: m["utime"])
        self.game_utimes = [m["utime"] for m in self.games]
        self.statuses = sorted(statuses, key=lambda m: m["utime"])
        self.status_utimes = [m["utime"] for m in self.statuses]
        self.robot_count = len({(s["team"], s["player"]) for s in self.statuses})
        self.senses = {s["frame"]: s for s in senses}  # paired with truths by frame
        self.events = sorted(events, key=lambda m: m["utime"])
        self.event_utimes = [m["utime"] for m in self.events]

    @classmethod
    def load(cls, path: Path) -> "ReplayLog":
        path = Path(path)
        if not path.is_file():
            raise ViewerError(f"log {path}: no such file")
        with open(path, "rb") as f:
            if f.read(4) != LCM_LOG_MAGIC:
                raise ViewerError(f"log {path} is not an lcm-logger log (empty or corrupt)")
        found = {MATCH: [], TRUTH: [], GAME: [], STATUS: [], SENSE: [], EVENT: []}
        raw_match, any_truth = None, False  # the first TL_MATCH as logged; whether any TL_TRUTH was
        try:
            for event in lcm.EventLog(str(path), "r"):
                if event.channel == MATCH and found[MATCH]:
                    continue  # the world repeats it unchanged: the first is the match's
                if event.channel in found:
                    any_truth = any_truth or event.channel == TRUTH
                    raw_match = event.data if raw_match is None and event.channel == MATCH else raw_match
                    message = decode(event.channel, event.data)
                    if message is not None:
                        found[event.channel].append(message)
        except (OSError, ValueError) as e:  # a truncated tail: keep what was read
            if not found[TRUTH]:
                raise ViewerError(f"log {path} cannot be read: {e}") from None
        if any_truth and not found[MATCH]:  # a match log this viewer cannot draw: say why
            raise ViewerError(missing_match_reason(path.name, raw_match))
        match = found[MATCH][0] if found[MATCH] else None
        return cls(path.name, match, found[TRUTH], found[GAME], found[STATUS], found[SENSE], found[EVENT])

    @property
    def count(self) -> int:
        return len(self.truths)

    @property
    def t0(self) -> float:
        return self.utimes[0] / 1e6

    @property
    def t1(self) -> float:
        return self.utimes[-1] / 1e6

    def index_at(self, t: float) -> int:
        """The last frame at or before sim time t (seconds), clamped to the log."""
        i = bisect_right(self.utimes, round(t * 1e6)) - 1
        return min(max(i, 0), self.count - 1)

    def frame(self, i: int) -> dict:
        truth = self.truths[i]
        g = bisect_right(self.game_utimes, truth["utime"]) - 1
        e = bisect_right(self.event_utimes, truth["utime"])
        return {"truth": truth, "sense": self.senses.get(truth["frame"]), "game": self.games[g] if g >= 0 else None,
                "status": self._statuses_at(truth["utime"]), "events": self.events[max(0, e - RECENT_EVENTS):e]}

    def _statuses_at(self, utime: int) -> list:
        latest = {}
        for j in range(bisect_right(self.status_utimes, utime) - 1, -1, -1):
            s = self.statuses[j]
            latest.setdefault((s["team"], s["player"]), s)
            if len(latest) == self.robot_count:
                break
        return [latest[k] for k in sorted(latest)]
