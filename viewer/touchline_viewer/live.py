"""Live view: subscribes to LCM and pushes the latest truth (with its frame's sonar), game
state, robot statuses, match events and each robot's belief and role (its TL_ACT_<team>_<player>)
to every connected page, at most ~30 times a second,
once the match's geometry (TL_MATCH) is known; a new TL_MATCH (another match) is a new hello."""
import asyncio
from collections import deque

import lcm

from .decode import ACT_PATTERN, CHANNELS, EVENT, GAME, RECENT_EVENTS, SENSE, STATUS, TRUTH, decode
from .errors import ViewerError
from .field import MATCH
from .home import touchline_paths
from .replay_log import BELIEF_STALE_FRAMES, ROLE_STALE_FRAMES

DEFAULT_LCM_URL = "udpm://239.255.76.67:7667?ttl=0"
SEND_PERIOD_S = 1 / 30
RECENT_ACTS = 8  # acts (and roles) kept per robot to pick the truth's own frame's
RECENT_GAMES = 8  # game states kept to pick the one current at the truth's time (they come at 1 Hz)


class LiveSource:
    """Owns the LCM instance; call start() inside the running event loop, stop() after."""

    def __init__(self, url: str = DEFAULT_LCM_URL):
        self.url = url
        # The world's messages on the URL's port, the robots' acts on the port above it.
        self.buses = []
        for lane in touchline_paths.lane_urls(url):
            try:
                self.buses.append(lcm.LCM(lane))
            except (RuntimeError, OSError, ValueError) as e:
                hint = " (no multicast route? ip route add 224.0.0.0/4 dev lo)" if lane.startswith("udpm") else ""
                raise ViewerError(f"cannot open LCM at {lane}: {e}{hint}") from None
        for channel in (*CHANNELS, ACT_PATTERN):
            for bus in self.buses:
                bus.subscribe(channel, self._on_message)
        self.match = None  # the latest TL_MATCH: the page draws nothing before it
        self.truth = self.sense = None  # sense: the TL_SENSE of the truth's frame
        self.games: deque = deque(maxlen=RECENT_GAMES)
        self._latest_sense = None
        self.statuses: dict = {}
        self.events: deque = deque(maxlen=RECENT_EVENTS)
        # The acts of frame k + 1 come right after the truth of frame k: a few are kept per robot
        # so that the truth drawn gets the act of its own frame, as in the replay.
        self.beliefs: dict = {}  # (team, player) -> deque of its latest acts' beliefs
        self.roles: dict = {}  # (team, player) -> deque of (frame, role) of its latest team messages naming one
        self.version = 0  # bumped by every decoded message
        self.clients: set = set()  # each has async hello(dict) and frame(dict)
        self._task = None

    def start(self) -> None:
        loop = asyncio.get_running_loop()
        for bus in self.buses:
            loop.add_reader(bus.fileno(), bus.handle)
        self._task = loop.create_task(self._broadcast())

    async def stop(self) -> None:
        for bus in self.buses:
            asyncio.get_running_loop().remove_reader(bus.fileno())
        if self._task:
            self._task.cancel()
            await asyncio.gather(self._task, return_exceptions=True)

    def hello(self) -> dict:
        return {"mode": "live", "source": self.url, "match": self.match}

    def game(self):
        """The game as of the truth's time, as the replay pairs them: a newer state may
        already have arrived ahead of its frame's truth."""
        return next((g for g in reversed(self.games) if g["utime"] <= self.truth["utime"]), None)

    def frame(self) -> dict:
        return {"truth": self.truth, "sense": self.sense, "game": self.game(),
                "status": [self.statuses[k] for k in sorted(self.statuses)], "events": list(self.events),
                "beliefs": self.beliefs_now(), "ack": None}

    def beliefs_now(self) -> list:
        """The beliefs of the truth's frame, as the replay picks them (ReplayLog.beliefs_at)."""
        frame, beliefs = self.truth["frame"], []
        for key in sorted(self.beliefs):
            belief = next((b for b in reversed(self.beliefs[key]) if b["frame"] <= frame), None)
            if belief is not None and frame - belief["frame"] <= BELIEF_STALE_FRAMES:
                role = next((r for f, r in reversed(self.roles.get(key, ())) if 0 <= frame - f <= ROLE_STALE_FRAMES), None)
                beliefs.append({**belief, "role": role})
        return beliefs

    def _on_message(self, channel: str, data: bytes) -> None:
        message = decode(channel, data)  # handlers never throw: a bad message is dropped
        if message is None:
            return
        if channel == MATCH:
            if message == self.match:
                return  # the world repeats it once a second: nothing new to draw
            self.match = message
        elif channel == TRUTH:
            self.truth = message
            sense = self._latest_sense
            self.sense = sense if sense and sense["frame"] == message["frame"] else None
        elif channel == SENSE:  # published just before its frame's truth
            self._latest_sense = message
            if self.truth and self.truth["frame"] == message["frame"]:
                self.sense = message
        elif channel == EVENT:
            self.events.append(message)
        elif channel == GAME:
            self.games.append(message)
        elif channel == STATUS:
            self.statuses[(message["team"], message["player"])] = message
        elif channel.startswith("TL_ACT_"):
            key = (message["team"], message["player"])
            self.beliefs.setdefault(key, deque(maxlen=RECENT_ACTS)).append(message)
            if message["role"] is not None:
                self.roles.setdefault(key, deque(maxlen=RECENT_ACTS)).append((message["frame"], message["role"]))
        self.version += 1

    async def _broadcast(self) -> None:
        sent, match_sent = 0, None
        while True:
            await asyncio.sleep(SEND_PERIOD_S)
            if self.version == sent or self.match is None or not self.clients:
                continue
            sent, clients = self.version, list(self.clients)
            if self.match is not match_sent:  # the geometry first: frames are drawn on it
                match_sent = self.match
                hello = self.hello()
                await asyncio.gather(*(client.hello(hello) for client in clients), return_exceptions=True)
            if self.truth is not None:
                frame = self.frame()
                await asyncio.gather(*(client.frame(frame) for client in clients), return_exceptions=True)
