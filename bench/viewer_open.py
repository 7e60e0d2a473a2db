"""Opening a match log in the viewer (see bench/viewer_open): the time from starting the server
on the log to the first frame drawn in a headless Chromium that is already running (the
browser's own start is not the viewer's), against the 3 s goal; the index pass alone; the
decoding of one frame on a seek; with --baseline, decoding every message up front as the
viewer did before the index (11.4 s for a 109 MB log when issue #16 was filed)."""
import argparse
import json
import random
import re
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

GOAL_S = 3.0
WAIT_S = 60


def open_to_first_frame(log: Path, context) -> float:
    """Seconds from starting `python -m touchline_viewer --log LOG` to its first frame drawn."""
    start = time.perf_counter()
    server = subprocess.Popen([sys.executable, "-m", "touchline_viewer", "--log", str(log), "--port", "0"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        line = []
        reader = threading.Thread(target=lambda: line.append(server.stdout.readline()), daemon=True)
        reader.start()
        reader.join(WAIT_S)
        url = re.search(r"http://127\.0\.0\.1:\d+/", line[0] if line else "")
        if not url:
            raise SystemExit(f"viewer_open: the viewer did not start: {server.stderr.read()}")
        page = context.new_page()
        page.goto(url.group(0))
        page.evaluate("window.viewer.ready")
        elapsed = time.perf_counter() - start
        page.close()
        return elapsed
    finally:
        server.terminate()
        server.wait(WAIT_S)


def index_s(log: Path):
    from touchline_viewer.replay_log import ReplayLog
    start = time.perf_counter()
    replay = ReplayLog.load(log)
    return time.perf_counter() - start, replay


def frame_ms(replay, samples: int = 200) -> float:
    """Mean milliseconds to decode one frame (truth, sense, beliefs and roles, statuses) at a
    random place: what a seek costs the server."""
    rng = random.Random(1)
    picks = [rng.randrange(replay.count) for _ in range(samples)]
    start = time.perf_counter()
    for i in picks:
        replay._frame(i)  # not the cache: each one decoded
    return (time.perf_counter() - start) / samples * 1e3


def decode_everything_s(log: Path) -> float:
    """The viewer before the index: every viewer message of the log decoded before the first frame."""
    import lcm
    from touchline_viewer.decode import decode
    channels = {"TL_MATCH", "TL_TRUTH", "TL_SENSE", "TL_GAME", "TL_STATUS", "TL_EVENT"}
    start = time.perf_counter()
    for event in lcm.EventLog(str(log), "r"):
        if event.channel in channels:
            decode(event.channel, event.data)
    return time.perf_counter() - start


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("log", type=Path)
    p.add_argument("--repeat", type=int, default=3, help="runs of the open (default 3; the median is the figure)")
    p.add_argument("--baseline", action="store_true", help="also time decoding every message up front (slow)")
    p.add_argument("--json", type=Path)
    args = p.parse_args()
    if args.repeat < 1:
        p.error("--repeat must be at least 1")
    if not args.log.is_file():
        print(f"viewer_open: no log {args.log}", file=sys.stderr)
        return 2
    size_mb = args.log.stat().st_size / 1e6
    index, replay = index_s(args.log)
    result = {"log": str(args.log), "size_mb": round(size_mb, 1), "frames": replay.count,
              "robots_with_acts": len(replay.index.acts), "timeline_markers": len(replay.timeline),
              "index_s": round(index, 3), "frame_ms": round(frame_ms(replay), 3)}
    from playwright.sync_api import sync_playwright
    from touchline_viewer.browser import launch_options
    with tempfile.TemporaryDirectory(prefix="touchline-chromium-") as profile, sync_playwright() as pw:
        context = pw.chromium.launch_persistent_context(profile, **launch_options(1100, 760))
        runs = [open_to_first_frame(args.log, context) for _ in range(args.repeat)]
        context.close()
    result["open_s"] = [round(r, 3) for r in runs]
    result["open_median_s"] = round(statistics.median(runs), 3)
    result["goal_s"] = GOAL_S
    result["ratio_to_goal"] = round(result["open_median_s"] / GOAL_S, 3)
    if args.baseline:
        result["decode_everything_s"] = round(decode_everything_s(args.log), 3)
    print(f"log {args.log.name}: {size_mb:.1f} MB, {replay.count} frames, acts of {len(replay.index.acts)} robots, "
          f"{len(replay.timeline)} timeline markers")
    print(f"index pass:            {index:.3f} s")
    print(f"one frame on a seek:   {result['frame_ms']:.2f} ms")
    print(f"open to first frame:   {result['open_median_s']:.3f} s (median of {len(runs)}: "
          f"{', '.join(f'{r:.3f}' for r in runs)})")
    print(f"against the 3 s goal:  {result['ratio_to_goal']:.2f} of it ({'met' if result['ratio_to_goal'] < 1 else 'MISSED'})")
    if args.baseline:
        print(f"decoding everything:   {result['decode_everything_s']:.3f} s (the viewer before the index)")
    if args.json:
        args.json.write_text(json.dumps(result, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
