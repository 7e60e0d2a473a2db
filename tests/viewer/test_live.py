"""The live view: the match's geometry (TL_MATCH) first, then LCM messages decoded and pushed
to the page, decimated to ~30 a second, each truth with its own frame's sonar and the robots'
beliefs and roles from their acts; a log played
into it with lcm-logplayer shows what the replay of that log shows."""
import asyncio
import json
import subprocess
import sys
from pathlib import Path

import aiohttp

from conftest import ROOT, viewer_env
from known_log import FRAMES, MATCH, SENSE_FRAMES, known_messages, match_config
from touchline_viewer.live import LiveSource
from touchline_viewer.replay_log import ReplayLog
from touchline_viewer.server import make_app, start


async def watch_memq(publish_all: bool, then_another_match: bool = False) -> tuple:
    """A live viewer on memq:// (in this process, no network); returns (hellos, frames received)."""
    source = LiveSource("memq://")
    runner, url = await start(make_app(source), 0)
    try:
        async with aiohttp.ClientSession() as session, session.ws_connect(url + "ws") as ws:
            hellos = [await ws.receive_json(timeout=10)]
            last = FRAMES - 1 if publish_all else 0
            for _, channel, message in known_messages():  # up to the last frame's truth
                source.buses[0].publish(channel, message.encode())
                if channel == "TL_TRUTH" and message.frame == last:
                    break
            frames = []
            while not frames or frames[-1]["truth"]["frame"] < last:
                message = await ws.receive_json(timeout=10)
                (hellos if message["type"] == "hello" else frames).append(message)
            if then_another_match:
                source.buses[0].publish("TL_MATCH", match_config(field_length_mm=9000.0).encode())
                hellos.append(await ws.receive_json(timeout=10))
            return hellos, frames
    finally:
        await runner.cleanup()


def test_the_page_learns_the_match_s_geometry_before_any_frame():
    hellos, frames = asyncio.run(watch_memq(publish_all=False))
    assert [h["type"] for h in hellos] == ["hello", "hello"]
    assert hellos[0]["mode"] == "live" and hellos[0]["match"] is None, "nothing known before TL_MATCH"
    assert hellos[1]["match"]["field"]["length_mm"] == MATCH["field_length_mm"]
    assert hellos[1]["match"]["camera"]["near_range_mm"] == MATCH["camera_near_range_mm"]
    assert frames, "frames follow once the geometry is known"


def test_another_match_on_the_bus_is_a_new_hello():
    hellos, _ = asyncio.run(watch_memq(publish_all=False, then_another_match=True))
    assert [h["match"]["field"]["length_mm"] for h in hellos[1:]] == [MATCH["field_length_mm"], 9000.0]


def test_published_truth_reaches_the_page_as_the_replay_decodes_it(known_log):
    _, frames = asyncio.run(watch_memq(publish_all=False))
    replayed = ReplayLog.load(known_log).frame(0)
    for part in ("truth", "sense", "game", "status", "events", "beliefs"):
        assert frames[-1][part] == replayed[part], part
    assert [b["role"] for b in frames[-1]["beliefs"]] == ["goalie", "striker", "goalie", "defender", "midfielder", None]
    assert frames[-1]["sense"]["frame"] == 0


def test_a_burst_is_decimated_to_the_latest_frame(known_log):
    _, frames = asyncio.run(watch_memq(publish_all=True))
    assert len(frames) < FRAMES, "a burst of messages is not forwarded one by one"
    assert frames[-1]["truth"]["frame"] == FRAMES - 1
    assert FRAMES - 1 not in SENSE_FRAMES and frames[-1]["sense"] is None, "never the previous frame's sonar"
    assert frames[-1]["events"] == ReplayLog.load(known_log).frame(FRAMES - 1)["events"]
    assert frames[-1]["beliefs"] == ReplayLog.load(known_log).frame(FRAMES - 1)["beliefs"], \
        "each robot's latest act, with the role of its last team message"


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
        assert live["beliefs"] == replayed["beliefs"], "TL_ACT_* live: the beliefs and roles the replay shows"
        assert live["game"]["secs_remaining"] == replayed["game"]["secs_remaining"]


def test_acts_on_the_robots_port_reach_the_live_view():
    """On udpm the robots answer on the port above the URL's (bridge/lcm lanes): the viewer
    listens there too, or it would show no belief and no role of a live match."""
    check = Path(__file__).with_name("live_lanes_check.py")
    result = subprocess.run([str(ROOT / "tools" / "netns"), sys.executable, str(check)],
                            env=viewer_env(), capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    held = {tuple(robot) for robot in json.loads(result.stdout)}
    sent = {(m.team, m.player) for _, channel, m in known_messages() if channel.startswith("TL_ACT_")}
    assert sent and held == sent
