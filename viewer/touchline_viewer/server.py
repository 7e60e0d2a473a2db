"""The web server: the page's static files on / and /static/, and on the /ws WebSocket a hello
(mode, source and the match's geometry) and then frames."""
import asyncio
import errno
import json
from pathlib import Path

from aiohttp import WSMsgType, web

from .errors import ViewerError
from .home import touchline_paths
from .live import LiveSource
from .replay import ReplaySession
from .replay_log import ReplayLog

HOST = "127.0.0.1"  # the viewer never listens on any other address
STATIC = touchline_paths.SHARE / "viewer" / "static"  # viewer/static, or its installed copy
SOURCE = web.AppKey("source", object)  # a LiveSource or a ReplayLog


def make_app(source) -> web.Application:
    app = web.Application()
    app[SOURCE] = source
    app.router.add_get("/", _index)
    app.router.add_get("/ws", _websocket)
    app.router.add_static("/static/", STATIC)
    if isinstance(source, LiveSource):
        app.on_startup.append(_start_live)
        app.on_cleanup.append(_stop_live)
    return app


async def start(app: web.Application, port: int) -> tuple:
    """Listens on 127.0.0.1:port (0: any free port); returns (runner, url)."""
    runner = web.AppRunner(app, handle_signals=False)
    await runner.setup()
    try:
        await web.TCPSite(runner, HOST, port).start()
    except OSError as e:
        await runner.cleanup()
        if e.errno == errno.EADDRINUSE:
            raise ViewerError(f"port {port} on {HOST} is in use (choose another with --port)") from None
        raise ViewerError(f"cannot listen on {HOST}:{port}: {e.strerror or e}") from None
    bound_port = runner.addresses[0][1]
    return runner, f"http://{HOST}:{bound_port}/"


async def _start_live(app: web.Application) -> None:
    app[SOURCE].start()


async def _stop_live(app: web.Application) -> None:
    await app[SOURCE].stop()


async def _index(request: web.Request) -> web.FileResponse:
    return web.FileResponse(STATIC / "index.html", headers={"Cache-Control": "no-store"})


async def _websocket(request: web.Request) -> web.WebSocketResponse:
    ws = web.WebSocketResponse()
    await ws.prepare(request)
    source = request.app[SOURCE]
    client = _Client(ws)
    if isinstance(source, ReplayLog):
        await _serve_replay(ws, source, client)
    else:
        await _serve_live(ws, source, client)
    return ws


class _Client:
    """One page's WebSocket: a hello (again whenever the match changes), then frames."""

    def __init__(self, ws: web.WebSocketResponse):
        self.ws = ws

    async def hello(self, hello: dict) -> None:
        await self.ws.send_str(json.dumps({"type": "hello", **hello}))

    async def frame(self, frame: dict) -> None:
        await self.ws.send_str(json.dumps({"type": "frame", **frame}, separators=(",", ":")))


async def _serve_replay(ws, log: ReplayLog, client: _Client) -> None:
    session = ReplaySession(log, client.frame)
    await client.hello(session.hello())
    player = asyncio.create_task(session.run())
    try:
        async for message in ws:
            if message.type == WSMsgType.TEXT:
                try:
                    command = json.loads(message.data)
                except ValueError:
                    continue
                if isinstance(command, dict):
                    session.commands.put_nowait(command)
    finally:
        player.cancel()
        await asyncio.gather(player, return_exceptions=True)


async def _serve_live(ws, live: LiveSource, client: _Client) -> None:
    await client.hello(live.hello())
    if live.truth is not None and live.match is not None:
        await client.frame(live.frame())
    live.clients.add(client)
    try:
        async for _ in ws:  # the live view takes no commands
            pass
    finally:
        live.clients.discard(client)
