"""python -m touchline_viewer: serves the match viewer on 127.0.0.1, live from LCM or replaying a log.

Live (default): subscribes to TL_MATCH, TL_TRUTH, TL_SENSE, TL_GAME, TL_STATUS and TL_EVENT on --lcm-url.
Replay: --log FILE opens an lcm-logger log; the page gets play, pause, step, scrub and speed.
The field, goals, ball, feet, camera and sonar are drawn with the sizes the match itself
publishes on TL_MATCH (the first message of its log)."""
import argparse
import asyncio
import signal
import sys
from pathlib import Path

from .errors import ViewerError, one_line
from .home import touchline_paths

DEFAULT_PORT = 8035
PROG = "touchline_viewer"


class OneLineParser(argparse.ArgumentParser):
    """argparse whose errors are one line on stderr and exit code 2."""

    def error(self, message: str):
        self.exit(2, f"{self.prog}: {message} (see --help)\n")


def port_number(text: str) -> int:
    port = int(text)
    if not 0 <= port <= 65535:
        raise ValueError(text)
    return port


port_number.__name__ = "port"  # argparse names the type in its message


def parse_args(argv) -> argparse.Namespace:
    p = OneLineParser(prog=PROG, description=__doc__.split("\n\n")[0])
    source = p.add_mutually_exclusive_group()
    source.add_argument("--log", type=Path, metavar="FILE", help="replay this lcm-logger log instead of watching live")
    source.add_argument("--lcm-url", metavar="URL", help="LCM URL to watch (default udpm://239.255.76.67:7667?ttl=0)")
    p.add_argument("--version", action="version", help="print the program's name and version and exit",
                   version=f"{PROG} {touchline_paths.version()}")
    p.add_argument("--port", type=port_number, default=DEFAULT_PORT,
                   help=f"port on 127.0.0.1 (default {DEFAULT_PORT}; 0 picks a free one)")
    return p.parse_args(argv)


def open_source(args):
    if args.log is not None:
        from .replay_log import ReplayLog
        return ReplayLog.load(args.log)
    from .live import DEFAULT_LCM_URL, LiveSource
    return LiveSource(args.lcm_url or DEFAULT_LCM_URL)


def describe(source) -> str:
    if hasattr(source, "count"):
        return f"replaying {source.name}: {source.count} frames, sim time {source.t0:.2f}..{source.t1:.2f} s"
    return f"live from {source.url}"


async def serve(source, port: int) -> None:
    from .server import make_app, start
    stop = asyncio.Event()
    loop = asyncio.get_running_loop()
    for sig in (signal.SIGINT, signal.SIGTERM):
        loop.add_signal_handler(sig, stop.set)
    runner, url = await start(make_app(source), port)
    print(f"touchline viewer: {url} ({describe(source)}); Ctrl-C stops", flush=True)
    try:
        await stop.wait()
    finally:
        await runner.cleanup()


def main(argv=None) -> int:
    args = parse_args(argv)
    try:
        source = open_source(args)
        asyncio.run(serve(source, args.port))
    except ViewerError as e:
        print(f"{PROG}: {one_line(e)}", file=sys.stderr)
        return 2
    return 0
