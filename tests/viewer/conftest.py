"""Fixtures for the viewer tests: the known log, the viewer server as a process, a headless page."""
import os
import re
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
VIEWER = ROOT / "viewer"
if str(VIEWER) not in sys.path:
    sys.path.insert(0, str(VIEWER))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from known_log import write_known_log  # noqa: E402

WAIT_S = 20  # the longest any step waits before the test fails
VIEWPORT = (1100, 760)


def viewer_env() -> dict:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(VIEWER), env.get("PYTHONPATH", "")) if p)
    return env


def run_module(module: str, *args, timeout: float = 60) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", module, *map(str, args)], env=viewer_env(),
                          capture_output=True, text=True, timeout=timeout)


class ViewerServer:
    """python -m touchline_viewer ARGS --port 0, until stopped; .url once it listens."""

    def __init__(self, *args):
        self.proc = subprocess.Popen([sys.executable, "-m", "touchline_viewer", *map(str, args), "--port", "0"],
                                     env=viewer_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = []
        reader = threading.Thread(target=lambda: line.append(self.proc.stdout.readline()), daemon=True)
        reader.start()
        reader.join(WAIT_S)
        found = re.search(r"http://127\.0\.0\.1:\d+/", line[0] if line else "")
        if not found:
            self.stop()
            raise RuntimeError(f"the viewer did not start: {self.proc.stderr.read() if self.proc.stderr else ''}")
        self.url = found.group(0)

    def stop(self) -> int:
        if self.proc.poll() is None:
            self.proc.terminate()
        return self.proc.wait(WAIT_S)


@pytest.fixture(scope="module")
def known_log(tmp_path_factory) -> Path:
    return write_known_log(tmp_path_factory.mktemp("log") / "known.lcmlog")


@pytest.fixture(scope="module")
def replay_server(known_log):
    server = ViewerServer("--log", known_log)
    yield server
    assert server.stop() == 0, "the viewer must exit 0 on SIGTERM"


@pytest.fixture(scope="module")
def browser():
    """A headless Chromium context (fresh profile); fails the test on any page error."""
    from playwright.sync_api import sync_playwright
    from touchline_viewer.browser import launch_options
    with tempfile.TemporaryDirectory(prefix="touchline-chromium-") as profile, sync_playwright() as pw:
        context = pw.chromium.launch_persistent_context(profile, **launch_options(*VIEWPORT))
        yield context
        context.close()


@pytest.fixture
def page(browser):
    page = browser.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type in ("error", "warning") else None)
    yield page
    page.close()
    assert errors == [], f"the page reported: {errors}"
