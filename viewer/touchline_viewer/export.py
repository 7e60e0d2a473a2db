"""python -m touchline_viewer.export: a PNG of one moment or an animated GIF of a span of a log.

Each image is a screenshot of the viewer's own page in headless Chromium (one renderer):
--at S writes a PNG; --from S --to S --fps N writes a GIF of round((to - from) * fps) frames,
at from, from + 1/fps, ... (each frame shows the last truth frame at or before its time)."""
import argparse
import asyncio
import io
import sys
from pathlib import Path

from PIL import Image

from .cli import OneLineParser
from .errors import ViewerError, one_line

PROG = "touchline_viewer.export"
MAX_FPS = 50  # GIF frame delays are in hundredths of a second


def size(text: str) -> tuple:
    w, h = (int(v) for v in text.lower().split("x"))
    if not (200 <= w <= 4000 and 150 <= h <= 4000):
        raise ValueError(text)
    return w, h


def parse_args(argv) -> argparse.Namespace:
    p = OneLineParser(prog=PROG, description=__doc__.split("\n\n")[0])
    p.add_argument("--log", type=Path, required=True, metavar="FILE", help="lcm-logger log to draw")
    p.add_argument("--at", type=float, metavar="S", help="sim time (seconds) of the PNG")
    p.add_argument("--from", dest="start", type=float, metavar="S", help="sim time the GIF starts")
    p.add_argument("--to", dest="end", type=float, metavar="S", help="sim time the GIF ends")
    p.add_argument("--fps", type=float, default=10.0, help=f"GIF frames per second (default 10, at most {MAX_FPS})")
    p.add_argument("--out", type=Path, help="output file (default: beside the log, named by the times)")
    p.add_argument("--size", type=size, default=(1100, 760), metavar="WxH", help="image size in pixels (default 1100x760)")
    args = p.parse_args(argv)
    span = args.start is not None or args.end is not None
    if (args.at is None) == (not span):
        p.error("give either --at S (a PNG) or --from S --to S (a GIF)")
    if span and (args.start is None or args.end is None or args.end <= args.start):
        p.error("a GIF needs --from S --to S with --to after --from")
    if not 0 < args.fps <= MAX_FPS:
        p.error(f"--fps must be in (0, {MAX_FPS}]")
    if args.out is None:
        stem = args.log.with_suffix("")
        args.out = Path(f"{stem}_at{args.at:g}.png" if args.at is not None else f"{stem}_{args.start:g}-{args.end:g}.gif")
    return args


def frame_times(start: float, end: float, fps: float) -> list:
    count = max(1, round((end - start) * fps))
    return [start + k / fps for k in range(count)]


def check_in_log(log, times: list) -> None:
    for t in (times[0], times[-1]):
        if not log.t0 - 1 / 30 <= t <= log.t1:  # the first frame's own 1/30 s counts
            raise ViewerError(f"time {t:g} s is outside the log ({log.t0:.2f}..{log.t1:.2f} s)")


async def screenshots(log, times: list, width: int, height: int) -> list:
    """One PNG (bytes) per time, from the viewer page served on a free port of 127.0.0.1."""
    from . import browser
    from .server import make_app, start
    runner, url = await start(make_app(log), 0)
    try:
        async with browser.page(width, height) as page:
            await page.goto(url + "?export=1")
            await page.evaluate("window.viewer.ready")
            shots = []
            for t in times:
                await page.evaluate("t => window.viewer.seek(t)", t)
                shots.append(await page.screenshot())
            return shots
    finally:
        await runner.cleanup()


def write(out: Path, shots: list, fps: float) -> None:
    images = [Image.open(io.BytesIO(png)).convert("RGB") for png in shots]
    out.parent.mkdir(parents=True, exist_ok=True)
    if out.suffix.lower() == ".gif" or len(images) > 1:
        images[0].save(out, format="GIF", save_all=True, append_images=images[1:],
                       duration=round(1000 / fps), loop=0)
    else:
        images[0].save(out, format="PNG")


def main(argv=None) -> int:
    args = parse_args(argv)
    try:
        from .replay_log import ReplayLog
        log = ReplayLog.load(args.log)
        times = [args.at] if args.at is not None else frame_times(args.start, args.end, args.fps)
        check_in_log(log, times)
        shots = asyncio.run(screenshots(log, times, *args.size))
        write(args.out, shots, args.fps)
    except ViewerError as e:
        print(f"{PROG}: {one_line(e)}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"{PROG}: cannot write {args.out}: {one_line(e)}", file=sys.stderr)
        return 2
    print(f"{PROG}: wrote {args.out} ({len(shots)} frame{'s' if len(shots) != 1 else ''})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
