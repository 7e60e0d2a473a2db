#!/usr/bin/env python3
"""tools/spy --text: a match's LCM bus in the terminal, where lcm-spy (Java, a window)
cannot go, e.g. over ssh: every channel with its message count and rate, the last message
decoded, the robots (status, place, chest LED) and the frame.

Messages are decoded with Touchline's generated Python types (build/lcm_types/gen/python),
chosen by each message's LCM fingerprint, so a channel of any name decodes. Each message
ends in the bus's 32-byte authentication tag (HMAC-SHA-256 over the channel, a zero byte and
the encoding: bridge/lcm/bus.hpp). With the match secret ($TOUCHLINE_MATCH_SECRET, as the
programs take it) the spy checks every tag and counts the messages without a valid one per
channel ("forged"), decoding only the others; without it, it cannot tell a forged message
from a real one, and says so.

A match's one URL carries its messages on three ports (bridge/lcm/include/touchline/lcm/lanes.hpp):
the world's on the URL's port, the robots' answers, joins and Blackboards on the port above,
and copies of what the robots need on the next; the spy listens to the first two.

  tools/spy --text                    live, until Ctrl-C
  tools/spy --text --once             one snapshot after --duration seconds (default 2), then exit
"""
from __future__ import annotations

import argparse
import hashlib
import hmac
import importlib
import math
import os
import select
import sys
import threading
import time
from collections import deque
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import touchline_paths  # noqa: E402
from touchline_version import add_version_option  # noqa: E402

DEFAULT_URL = "udpm://239.255.76.67:7667?ttl=0"
RATE_WINDOW_S = 2.0  # wall seconds a channel's rate is measured over
TAG_BYTES = 32       # the authentication tag after every encoding (bridge/lcm bus.hpp)
TYPE_NAMES = ("act_t", "blackboard_snapshot_t", "game_state_t", "join_reply_t", "join_t", "match_config_t",
              "match_event_t", "robot_status_t", "sense_t", "team_message_t", "world_truth_t")
STATUS_NAMES = {1: "joined", 2: "active", 3: "timed out", 4: "rejoined", 5: "rejected"}
GAME_STATES = {0: "INITIAL", 1: "READY", 2: "SET", 3: "PLAYING", 4: "FINISHED", 5: "STANDBY"}


def load_types(build_dir: Path) -> dict:
    """LCM fingerprint (8 bytes) -> generated type, for every Touchline type there is."""
    sys.path[:0] = touchline_paths.lcm_python_dirs(build_dir)
    types = {}
    for name in TYPE_NAMES:
        try:
            t = getattr(importlib.import_module(f"touchline.{name}"), name)
        except (ImportError, AttributeError):
            continue  # a build with other types: that channel shows undecoded
        types[t._get_packed_fingerprint()] = t
    if not types:
        raise SystemExit(f"tools/spy: no LCM types under {build_dir}/lcm_types/gen/python: run tools/setup first")
    return types


def brief(value, depth: int = 0) -> str:
    """A decoded message (or field) in one short line: numbers, sizes of arrays, one level of nesting."""
    if hasattr(value, "__slots__"):
        if depth > 0:
            return "{" + " ".join(f"{s}={brief(getattr(value, s), depth + 1)}" for s in value.__slots__[:3]) + "}"
        return " ".join(f"{s}={brief(getattr(value, s), depth + 1)}" for s in value.__slots__)
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, (list, tuple)):
        if len(value) <= 2 and all(isinstance(v, (int, float)) for v in value):
            return "[" + ",".join(brief(v, depth + 1) for v in value) + "]"
        return f"[{len(value)}]"
    if isinstance(value, (bytes, bytearray)):
        return f"<{len(value)} bytes>"
    if isinstance(value, str):
        return repr(value if len(value) <= 40 else value[:39] + "…")
    return str(value)


class Channel:
    def __init__(self):
        self.count = 0
        self.forged = 0              # messages without a valid tag (only known with the secret)
        self.bytes = 0
        self.times: deque = deque()  # wall times of the last RATE_WINDOW_S
        self.last = None             # the last decoded message, or None
        self.last_error = ""         # why the last message did not decode

    def rate(self, now: float, watched_s: float) -> float:
        """Messages a second over the last RATE_WINDOW_S (or as long as the spy has watched)."""
        while self.times and now - self.times[0] > RATE_WINDOW_S:
            self.times.popleft()
        return len(self.times) / max(1e-3, min(RATE_WINDOW_S, watched_s))


class Spy:
    """Everything heard on the bus, kept per channel; the robots and the frame from the world's messages."""

    def __init__(self, url: str, types: dict, secret: bytes | None = None):
        import lcm

        self.url = url
        self.secret = secret
        self.types = types
        self.channels: dict[str, Channel] = {}
        self.robots: dict = {}  # (team, player) -> dict of what is known
        self.frame = None
        self.sim_s = None
        self.game = ""
        self.lock = threading.Lock()
        self.started = time.monotonic()
        self.buses = [lcm.LCM(lane) for lane in touchline_paths.lane_urls(url)]  # the world's port, then the robots'
        for bus in self.buses:
            bus.subscribe(".*", self._on_message)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="spy", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        buses = {bus.fileno(): bus for bus in self.buses}
        while not self._stop.is_set():
            for fd in select.select(list(buses), [], [], 0.1)[0]:
                buses[fd].handle()

    def _on_message(self, channel: str, data: bytes) -> None:
        now = time.monotonic()
        with self.lock:
            c = self.channels.setdefault(channel, Channel())
            c.count += 1
            c.bytes += len(data)
            c.times.append(now)
            if self.secret is not None:
                payload, tag = data[:-TAG_BYTES], data[-TAG_BYTES:]
                expected = hmac.new(self.secret, channel.encode() + b"\0" + payload, hashlib.sha256).digest()
                if len(data) < TAG_BYTES or not hmac.compare_digest(tag, expected):
                    c.forged += 1
                    return  # not the match's: neither shown nor counted among the robots
            msg_type = self.types.get(data[:8])
            if msg_type is None:
                c.last, c.last_error = None, "not a Touchline type"
                return
            try:  # anyone may publish anything: a message that does not decode is shown as such
                c.last = msg_type.decode(data)
                c.last_error = ""
            except Exception as e:
                c.last, c.last_error = None, f"{type(e).__name__}: {e}"
                return
            self._note(c.last)

    def _note(self, msg) -> None:
        name = type(msg).__name__
        if name == "world_truth_t":
            self.frame, self.sim_s = msg.frame, msg.utime / 1e6
            for r in msg.robots:
                self.robots.setdefault((r.team, r.player), {}).update(
                    x=r.body.x_mm, y=r.body.y_mm, theta=r.body.theta_rad, led=r.chest_led,
                    flags=", ".join(f for f, on in (("inactive", not r.active), ("penalised", r.penalised),
                                                    ("fallen", r.fallen)) if on))
        elif name == "sense_t" and self.frame is None:
            self.frame, self.sim_s = msg.frame, msg.utime / 1e6
        elif name == "robot_status_t":
            self.robots.setdefault((msg.team, msg.player), {}).update(
                status=STATUS_NAMES.get(msg.state, str(msg.state)), answered=msg.frames_answered,
                missed=msg.frames_missed)
        elif name == "game_state_t":
            self.game = f"{GAME_STATES.get(msg.state, msg.state)} {msg.score[0]}:{msg.score[1]}"

    def render(self, width: int = 120):
        from rich.console import Group
        from rich.table import Table

        now = time.monotonic()
        with self.lock:
            frame = "-" if self.frame is None else f"{self.frame} ({self.sim_s:.1f} s simulated)"
            head = (f"{self.url}: {len(self.channels)} channels, frame {frame}"
                    + (f", game {self.game}" if self.game else "")
                    + f"; {now - self.started:.0f} s watched; "
                    + ("tags checked with the match secret" if self.secret is not None
                       else "tags not verified (no match secret)"))
            channels = Table(title=head, title_justify="left", expand=False)
            for column, justify in (("channel", "left"), ("msgs", "right"), ("Hz", "right"),
                                    ("bytes", "right"), *((("forged", "right"),) if self.secret else ()),
                                    ("last message", "left")):
                channels.add_column(column, justify=justify, no_wrap=True,
                                    max_width=max(20, width - 50) if column == "last message" else None)
            for name in sorted(self.channels):
                c = self.channels[name]
                last = (brief(c.last) if c.last is not None else f"(undecoded: {c.last_error})" if c.last_error
                        else "(none with a valid tag)")
                size = c.bytes // c.count
                forged = (str(c.forged),) if self.secret else ()
                channels.add_row(name, str(c.count), f"{c.rate(now, now - self.started):.1f}", str(size), *forged, last)
            robots = Table(title="robots", title_justify="left")
            for column in ("robot", "status", "answered", "missed", "x mm", "y mm", "heading rad", "chest", "flags"):
                robots.add_column(column, no_wrap=True)
            for (team, player), r in sorted(self.robots.items()):
                robots.add_row(f"{team}/{player}", r.get("status", "-"), str(r.get("answered", "-")),
                               str(r.get("missed", "-")), num(r.get("x")), num(r.get("y")),
                               num(r.get("theta"), ".2f"), f"#{r['led']:06x}" if "led" in r else "-",
                               r.get("flags", ""))
        return Group(channels, robots) if self.robots else channels

    def heard(self) -> int:
        with self.lock:
            return sum(c.count for c in self.channels.values())

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(timeout=2)


def num(value, fmt: str = ".0f") -> str:
    return "-" if value is None or not math.isfinite(value) else format(value, fmt)


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="tools/spy --text", description=__doc__.split("\n\n")[0])
    add_version_option(p, "tools/spy")
    p.add_argument("--text", action="store_true", help="(what tools/spy passes on: this view)")
    p.add_argument("--lcm-url", default=os.environ.get("TOUCHLINE_LCM_URL", DEFAULT_URL),
                   help=f"the bus to watch (default $TOUCHLINE_LCM_URL or {DEFAULT_URL})")
    p.add_argument("--build-dir", type=Path, default=touchline_paths.build_dir(),
                   help="where the generated LCM types are")
    p.add_argument("--once", action="store_true", help="print one snapshot after --duration seconds and exit "
                   "(1 if nothing was heard)")
    p.add_argument("--duration", type=float, default=2.0, help="seconds to listen with --once (default 2)")
    args = p.parse_args(argv)
    if not (args.duration > 0 and math.isfinite(args.duration)):
        p.error("--duration must be a number of seconds > 0")
    return args


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    types = load_types(args.build_dir)
    secret = os.environ.get("TOUCHLINE_MATCH_SECRET")
    try:
        key = bytes.fromhex(secret) if secret else None
    except ValueError:
        print("tools/spy: $TOUCHLINE_MATCH_SECRET is not hex (the match secret the programs take)", file=sys.stderr)
        return 2
    try:
        spy = Spy(args.lcm_url, types, key)
    except Exception as e:  # LCM cannot open the URL
        print(f"tools/spy: cannot open LCM at {args.lcm_url}: {e}", file=sys.stderr)
        return 2
    from rich.console import Console

    console = Console()
    try:
        if args.once:
            time.sleep(args.duration)  # listening for a fixed time is what --once asks for
            console.print(spy.render(console.width))
            if not spy.heard():
                print(f"tools/spy: nothing heard on {args.lcm_url} in {args.duration:g} s", file=sys.stderr)
                return 1
            return 0
        from rich.live import Live
        with Live(spy.render(console.width), console=console, refresh_per_second=4, screen=False) as live:
            while True:
                time.sleep(0.25)
                live.update(spy.render(console.width))
    except KeyboardInterrupt:
        return 130
    finally:
        spy.stop()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
