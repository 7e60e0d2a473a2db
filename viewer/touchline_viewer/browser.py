"""Headless Chromium (Debian's, driven by Playwright) for the exporter and the tests."""
import os
import shutil
import tempfile
from contextlib import asynccontextmanager

from .errors import ViewerError

CHROMIUM = os.environ.get("TOUCHLINE_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def chromium_path() -> str:
    if not (os.path.isfile(CHROMIUM) and os.access(CHROMIUM, os.X_OK)):
        raise ViewerError(f"no Chromium at {CHROMIUM} (apt-get install chromium, or set TOUCHLINE_CHROMIUM)")
    return CHROMIUM


def launch_options(width: int, height: int) -> dict:
    """Keyword arguments for Playwright's chromium.launch_persistent_context (after the profile dir)."""
    return {"executable_path": chromium_path(), "args": CHROMIUM_ARGS, "headless": True,
            "viewport": {"width": width, "height": height}, "device_scale_factor": 1}


@asynccontextmanager
async def page(width: int, height: int):
    """A fresh headless page of width x height CSS pixels, in a fresh throw-away profile."""
    from playwright.async_api import async_playwright
    profile = tempfile.mkdtemp(prefix="touchline-chromium-")
    try:
        async with async_playwright() as pw:
            context = await pw.chromium.launch_persistent_context(profile, **launch_options(width, height))
            try:
                yield context.pages[0] if context.pages else await context.new_page()
            finally:
                await context.close()
    finally:
        shutil.rmtree(profile, ignore_errors=True)
