"""Run inside tools/netns: a live viewer on a udpm URL hears the world's messages on the URL's
port and the robots' acts on the port above it, where a match sends them (bridge/lcm lanes).
Publishes the known log's messages so, then waits until the viewer holds every active robot's
belief; prints the robots it holds as JSON. Usage: live_lanes_check.py"""
import asyncio
import json
import sys

import lcm

from known_log import known_messages
from touchline_viewer.home import touchline_paths
from touchline_viewer.live import DEFAULT_LCM_URL, LiveSource

WAIT_S = 10


async def main() -> list:
    source = LiveSource(DEFAULT_LCM_URL)
    world_port, robots_port = (lcm.LCM(url) for url in touchline_paths.lane_urls(DEFAULT_LCM_URL))
    source.start()
    try:
        acts = set()
        for _, channel, message in known_messages():
            (robots_port if channel.startswith("TL_ACT_") else world_port).publish(channel, message.encode())
            if channel.startswith("TL_ACT_"):
                acts.add((message.team, message.player))
        loop = asyncio.get_running_loop()
        deadline = loop.time() + WAIT_S
        while set(source.beliefs) != acts and loop.time() < deadline:
            await asyncio.sleep(0.01)  # the viewer's reader callbacks run meanwhile
        return sorted(source.beliefs)
    finally:
        await source.stop()


if __name__ == "__main__":
    print(json.dumps(asyncio.run(main())))
    sys.exit(0)
