"""One browser's replay of a log: play, pause, step, seek and speed, paced in sim time."""
import asyncio
import time

from .replay_log import ReplayLog

SPEEDS = (0.25, 0.5, 1.0, 2.0, 4.0, 8.0)
SEND_PERIOD_S = 1 / 30  # at most ~30 frames a second to the browser, whatever the speed


class ReplaySession:
    """Playback state of one connection; `commands` carries the page's commands (dicts)."""

    def __init__(self, log: ReplayLog, send, clock=time.monotonic):
        self.log, self.send, self.clock = log, send, clock
        self.index, self.playing, self.speed = 0, False, 1.0
        self.commands: asyncio.Queue = asyncio.Queue()
        self._anchor = (0.0, 0.0)  # (wall clock, sim seconds) when play last (re)started

    def hello(self) -> dict:
        return {"mode": "replay", "source": self.log.name, "match": self.log.match, "speeds": SPEEDS,
                "replay": {"t0": self.log.t0, "t1": self.log.t1, "count": self.log.count},
                "timeline": self.log.timeline}

    async def run(self) -> None:
        """Sends the first frame, then obeys commands and plays until cancelled."""
        await self._send_frame(ack=None)
        while True:
            try:
                timeout = SEND_PERIOD_S if self.playing else None
                command = await asyncio.wait_for(self.commands.get(), timeout)
            except asyncio.TimeoutError:
                if self._advance():
                    await self._send_frame(ack=None)
                continue
            self.apply(command)
            await self._send_frame(ack=command.get("seq"))

    def apply(self, command: dict) -> None:
        """Applies one command; unknown or malformed ones change nothing (and are still acked)."""
        cmd = command.get("cmd")
        try:
            if cmd == "play":
                self._play(True)
            elif cmd == "pause":
                self._play(False)
            elif cmd == "toggle":
                self._play(not self.playing)
            elif cmd == "step":
                self._play(False)
                self.index = min(max(self.index + int(command.get("n", 1)), 0), self.log.count - 1)
            elif cmd == "seek":  # "after": the first frame at or after t (a timeline marker's effect)
                t = float(command["t"])
                self.index = self.log.index_after(t) if command.get("after") else self.log.index_at(t)
                self._reanchor()
            elif cmd == "speed":
                self.speed = min(SPEEDS, key=lambda s: abs(s - float(command["x"])))
                self._reanchor()
        except (KeyError, TypeError, ValueError):
            pass

    def _play(self, on: bool) -> None:
        if on and self.index >= self.log.count - 1:
            self.index = 0  # play at the end starts over
        self.playing = on
        self._reanchor()

    def _reanchor(self) -> None:
        self._anchor = (self.clock(), self.log.utimes[self.index] / 1e6)

    def _advance(self) -> bool:
        """Moves to the frame the play clock has reached; True when the frame changed."""
        wall0, sim0 = self._anchor
        t = sim0 + (self.clock() - wall0) * self.speed
        index = self.log.index_at(t)
        if index >= self.log.count - 1:
            self.playing = False
        changed = index != self.index or not self.playing
        self.index = index
        return changed

    async def _send_frame(self, ack) -> None:
        frame = dict(self.log.frame(self.index))  # the log's frames are cached: add to a copy
        frame["replay"] = {"index": self.index, "count": self.log.count, "t": self.log.utimes[self.index] / 1e6,
                           "playing": self.playing, "speed": self.speed}
        frame["ack"] = ack
        await self.send(frame)
