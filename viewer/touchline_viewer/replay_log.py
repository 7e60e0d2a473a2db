"""An lcm-logger log opened for replay: indexed in one streaming pass (log_index.py), its frames
decoded when a page asks for them. Loading decodes only the match's geometry (its first
TL_MATCH), the game states, the match events (for the timeline) and the statuses' times; a frame
is its truth, its sense's sonar, each robot's belief and role (from its TL_ACT), the game state
and statuses at its time and the latest match events."""
from bisect import bisect_left, bisect_right
from functools import lru_cache
from pathlib import Path

from .decode import EVENT, GAME, RECENT_EVENTS, SENSE, STATUS, TRUTH, decode
from .errors import ViewerError
from .field import MATCH, missing_match_reason
from .log_index import LCM_LOG_MAGIC, LogIndex
from .timeline import timeline

BELIEF_STALE_FRAMES = 30  # a robot's last act older than this (1 s) is no belief of this frame
ROLE_STALE_FRAMES = 60    # our Team behaviours forget a teammate's message after 2 s: so does the viewer
FRAME_CACHE = 256         # decoded frames kept (scrubbing back and forth)


class ReplayLog:
    """Read-only after loading; shared by every replay connection."""

    def __init__(self, index: LogIndex, match: dict, games: list, events: list, statuses: list):
        if not index.truth_utimes:
            raise ViewerError(f"log {index.path.name} has no {TRUTH} messages to show")
        self.index, self.name, self.match = index, index.path.name, match
        self._order = sorted(range(len(index.truth_utimes)), key=index.truth_utimes.__getitem__)
        self.utimes = [index.truth_utimes[i] for i in self._order]
        self.games = sorted(games, key=lambda m: m["utime"])
        self.game_utimes = [m["utime"] for m in self.games]
        self.events = sorted(events, key=lambda m: m["utime"])
        self.event_utimes = [m["utime"] for m in self.events]
        self.statuses = sorted(statuses, key=lambda s: s[0])  # (utime, team, player, raw bytes)
        self.status_utimes = [s[0] for s in self.statuses]
        self.robot_count = len({s[1:3] for s in self.statuses})
        self.timeline = timeline(self.games, self.events)
        self.frame = lru_cache(maxsize=FRAME_CACHE)(self._frame)

    @classmethod
    def load(cls, path: Path) -> "ReplayLog":
        path = Path(path)
        if not path.is_file():
            raise ViewerError(f"log {path}: no such file")
        with open(path, "rb") as f:
            if f.read(4) != LCM_LOG_MAGIC.to_bytes(4, "big"):
                raise ViewerError(f"log {path} is not an lcm-logger log (empty or corrupt)")
        try:
            index = LogIndex(path)
        except OSError as e:
            raise ViewerError(f"log {path} cannot be read: {e}") from None
        match = decode(MATCH, index.first_match) if index.first_match is not None else None
        if index.truth_utimes and match is None:  # a match log this viewer cannot draw: say why
            raise ViewerError(missing_match_reason(path.name, index.first_match))
        games = [g for g in map(lambda d: decode(GAME, d), index.raw[GAME]) if g is not None]
        events = [e for e in map(lambda d: decode(EVENT, d), index.raw[EVENT]) if e is not None]
        statuses = [_status_key(d) for d in index.raw[STATUS]]
        return cls(index, match, games, events, [s for s in statuses if s is not None])

    @property
    def count(self) -> int:
        return len(self.utimes)

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

    def index_after(self, t: float) -> int:
        """The first frame at or after sim time t (seconds), clamped to the log."""
        return min(bisect_left(self.utimes, round(t * 1e6)), self.count - 1)

    def _frame(self, i: int) -> dict:
        truth = decode(TRUTH, self.index.truth_bytes(self._order[i]))
        if truth is None:  # a corrupt truth in the middle of the log: show the frame empty
            truth = {"utime": self.utimes[i], "frame": self.index.truth_frames[self._order[i]], "ball": None,
                     "robots": []}
        sense_at = self.index.sense_at.get(truth["frame"])
        g = bisect_right(self.game_utimes, truth["utime"]) - 1
        e = bisect_right(self.event_utimes, truth["utime"])
        return {"truth": truth, "sense": decode(SENSE, self.index.bytes_at(*sense_at)) if sense_at else None,
                "game": self.games[g] if g >= 0 else None, "status": self._statuses_at(truth["utime"]),
                "events": self.events[max(0, e - RECENT_EVENTS):e], "beliefs": self.beliefs_at(truth["frame"])}

    def beliefs_at(self, frame: int) -> list:
        """Each robot's belief from its act for `frame` (or its latest before, at most
        BELIEF_STALE_FRAMES old), with the role of its latest team message (at most
        ROLE_STALE_FRAMES old); robots by (team, player). Empty for a log without acts."""
        beliefs = []
        for robot in sorted(self.index.acts):
            frames, at = self.index.acts[robot]
            k = bisect_right(frames, frame) - 1
            if k < 0 or frame - frames[k] > BELIEF_STALE_FRAMES:
                continue
            belief = self._act(at[2 * k], at[2 * k + 1])
            if belief is None:
                continue
            belief = dict(belief)
            j = k
            while belief["role"] is None and j > 0 and frame - frames[j - 1] <= ROLE_STALE_FRAMES:
                j -= 1
                earlier = self._act(at[2 * j], at[2 * j + 1])
                belief["role"] = earlier["role"] if earlier else None
            beliefs.append(belief)
        return beliefs

    @lru_cache(maxsize=4096)
    def _act(self, offset: int, length: int):
        return decode("TL_ACT_", self.index.bytes_at(offset, length))

    def _statuses_at(self, utime: int) -> list:
        latest = {}
        for j in range(bisect_right(self.status_utimes, utime) - 1, -1, -1):
            _, team, player, raw = self.statuses[j]
            if (team, player) not in latest:
                status = decode(STATUS, raw)
                if status is not None:
                    latest[(team, player)] = status
            if len(latest) == self.robot_count:
                break
        return [latest[k] for k in sorted(latest)]


def _status_key(data: bytes):
    """(utime, team, player, data) of a robot_status_t, read from its first fields (after the
    fingerprint: utime, team, player) so that statuses are decoded only when shown."""
    if len(data) < 18:
        return None
    return (int.from_bytes(data[8:16], "big", signed=True), int.from_bytes(data[16:17], "big", signed=True),
            int.from_bytes(data[17:18], "big", signed=True), data)
