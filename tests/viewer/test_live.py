"""The live view: LCM messages decoded and pushed to the page, decimated to ~30 a second,
each truth with its own frame's sonar; a log played into it with lcm-logplayer shows what
the replay of that log shows."""
import asyncio
import json
import subprocess
import sys
from pathlib import Path

import aiohttp

from conftest import ROOT, viewer_env
from known_log import FRAMES, SENSE_FRAMES, known_messages
from touchline_viewer.field import load_field
from touchline_viewer.live import LiveSource
from touchline_viewer.replay_log import ReplayLog
from touchline_viewer.server import make_app, start

FIELD = load_field(ROOT / "config" / "spl2011.ini")


async def watch_memq(publish_all: bool) -> tuple:
    """A live viewer on memq:// (in this process, no network); returns (hello, frames received)."""
    source = LiveSource("memq://")
    runner, url = await start(make_app(source, FIELD), 0)
    try:
        async with aiohttp.ClientSession() as session, session.ws_connect(url + "ws") as ws:
            hello = await ws.receive_json(timeout=10)
            last = FRAMES - 1 if publish_all else 0
            for _, channel, message in known_messages():  # up to the last frame's truth
                source.lc.publish(channel, message.encode())
                if channel == "TL_TRUTH" and message.frame == last:
                    break
            frames = []
            while not frames or frames[-1]["truth"]["frame"] < last:
                frames.append(await ws.receive_json(timeout=10))
            return hello, frames
    finally:
        await runner.cleanup()


def test_published_truth_reaches_the_page_as_the_replay_decodes_it(known_log):
    hello, frames = asyncio.run(watch_memq(publish_all=False))
    assert hello["mode"] == "live" and hello["field"]["length_mm"] == 6000
    replayed = ReplayLog.load(known_log).frame(0)
    for part in ("truth", "sense", "game", "status", "events"):
        assert frames[-1][part] == replayed[part], part
    assert frames[-1]["sense"]["frame"] == 0


def test_a_burst_is_decimated_to_the_latest_frame(known_log):
    _, frames = asyncio.run(watch_memq(publish_all=True))
    assert len(frames) < FRAMES, "a burst of messages is not forwarded one by one"
    assert frames[-1]["truth"]["frame"] == FRAMES - 1
    assert FRAMES - 1 not in SENSE_FRAMES and frames[-1]["sense"] is None, "never the previous frame's sonar"
    assert frames[-1]["events"] == ReplayLog.load(known_log).frame(FRAMES - 1)["events"]


def test_a_log_played_with_lcm_logplayer_shows_what_its_replay_shows(known_log):
    check = Path(__file__).with_name("live_logplayer_check.py")
    result = subprocess.run([str(ROOT / "tools" / "netns"), sys.executable, str(check), str(known_log), str(FRAMES - 1)],
                            env=viewer_env(), capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    frames = json.loads(result.stdout)
    replay = ReplayLog.load(known_log)
    assert frames and frames[-1]["truth"]["frame"] == FRAMES - 1
    for live in frames:
        replayed = replay.frame(live["truth"]["frame"])
        assert live["truth"] == replayed["truth"]
        assert live["sense"] == replayed["sense"]
        assert live["game"]["secs_remaining"] == replayed["game"]["secs_remaining"]
