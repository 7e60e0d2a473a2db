"""Run inside tools/netns: the viewer watching live LCM while lcm-logplayer plays a log into it.
Prints the frames the viewer's WebSocket pushed, as one JSON list, on stdout.
Usage: live_logplayer_check.py LOG LAST_FRAME"""
import asyncio
import json
import re
import subprocess
import sys

import aiohttp

WAIT_S = 15


async def main(log: str, last_frame: int) -> list:
    viewer = await asyncio.create_subprocess_exec(sys.executable, "-m", "touchline_viewer", "--port", "0",
                                                  stdout=subprocess.PIPE)
    try:
        line = (await asyncio.wait_for(viewer.stdout.readline(), WAIT_S)).decode()
        url = re.search(r"http://127\.0\.0\.1:\d+/", line).group(0)
        frames = []
        async with aiohttp.ClientSession() as session, session.ws_connect(url + "ws") as ws:
            assert (await ws.receive_json(timeout=WAIT_S))["mode"] == "live"
            player = await asyncio.create_subprocess_exec("lcm-logplayer", log, stdout=subprocess.DEVNULL)
            try:
                while not frames or frames[-1]["truth"]["frame"] < last_frame:
                    message = await ws.receive_json(timeout=WAIT_S)
                    if message["type"] == "frame":  # not the hello that brings the match's TL_MATCH
                        frames.append(message)
            finally:
                await player.wait()
        return frames
    finally:
        viewer.terminate()
        await viewer.wait()


if __name__ == "__main__":
    print(json.dumps(asyncio.run(main(sys.argv[1], int(sys.argv[2])))))
