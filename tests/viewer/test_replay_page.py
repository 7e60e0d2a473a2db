"""The page in headless Chromium, replaying the known log: robots and ball drawn where the
log says (page state and pixels), step, scrub and play, and the README's screenshot."""
import io
import json
import os
import shutil
from pathlib import Path

import pytest
from PIL import Image

from conftest import ROOT, VIEWPORT, WAIT_S
from known_log import FRAMES, ROBOTS, SCORE, ball_at, robot_at, utime_of
from touchline_viewer.field import load_field

FIELD = load_field(ROOT / "config" / "spl2011.ini")
TEAM_RGB = {0: (0x1E, 0x63, 0xFF), 1: (0xE8, 0x23, 0x2A)}
INACTIVE_RGB = (0x8C, 0x8C, 0x8C)
BALL_RGB = (0xFF, 0x7F, 0x00)


def drawn(page) -> dict:
    return json.loads(page.locator("#state").text_content())


def open_viewer(page, url: str) -> dict:
    page.goto(url)
    page.evaluate("window.viewer.ready")
    return drawn(page)


def wait_for_frame(page, k: int) -> dict:
    page.wait_for_function("k => JSON.parse(document.getElementById('state').textContent).frame === k",
                           arg=k, timeout=WAIT_S * 1000)
    return drawn(page)


def expected_pixel(state: dict, x: float, y: float) -> tuple:
    """Where field point (x, y) mm must be on the canvas: the field and border fitted, centred."""
    w, h = state["canvas"]["width"], state["canvas"]["height"]
    s = min(w / (FIELD["length_mm"] + 2 * FIELD["border_mm"]), h / (FIELD["width_mm"] + 2 * FIELD["border_mm"]))
    return w / 2 + x * s, h / 2 - y * s


def assert_drawn_at(state: dict, place: dict, pose) -> None:
    assert place["x"] == pytest.approx(pose[0], abs=0.06) and place["y"] == pytest.approx(pose[1], abs=0.06)
    px, py = expected_pixel(state, pose[0], pose[1])
    assert place["px"] == pytest.approx(px, abs=0.06) and place["py"] == pytest.approx(py, abs=0.06)


def assert_shows_frame(state: dict, k: int) -> None:
    assert (state["frame"], state["utime"]) == (k, utime_of(k))
    assert_drawn_at(state, state["ball"], ball_at(k))
    robots = {(r["team"], r["player"]): r for r in state["robots"]}
    assert len(robots) == len(ROBOTS)
    for spec in ROBOTS:
        want, got = robot_at(spec, k), robots[spec[:2]]
        assert got["active"] == want["active"]
        for part in ("body", "left", "right"):
            assert_drawn_at(state, got[part], want[part])


def colour_near(image: Image.Image, px: float, py: float, rgb: tuple, tolerance: int = 12) -> bool:
    found = image.getpixel((round(px), round(py)))[:3]
    return all(abs(a - b) <= tolerance for a, b in zip(found, rgb)), found


def test_the_first_frame_is_drawn_where_the_log_says(page, replay_server):
    state = open_viewer(page, replay_server.url)
    assert state["mode"] == "replay"
    assert state["canvas"] == {"width": VIEWPORT[0], "height": page.locator("#field").bounding_box()["height"]}
    assert_shows_frame(state, 0)
    assert page.locator("#score0").text_content() == str(SCORE[0])
    assert page.locator("#score1").text_content() == str(SCORE[1])
    assert page.locator("#clock").text_content() == "10:00"
    assert "PLAYING" in page.locator("#game-state").text_content()
    assert "sim 0.03 s" in page.locator("#simtime").text_content()
    assert page.locator("#controls").is_visible()


def test_ball_and_feet_pixels_have_their_colours(page, replay_server):
    state = open_viewer(page, replay_server.url)
    image = Image.open(io.BytesIO(page.locator("#field").screenshot())).convert("RGB")
    assert image.size == (state["canvas"]["width"], state["canvas"]["height"])
    ok, found = colour_near(image, state["ball"]["px"], state["ball"]["py"], BALL_RGB)
    assert ok, f"ball pixel is {found}"
    for robot in state["robots"]:
        rgb = TEAM_RGB[robot["team"]] if robot["active"] else INACTIVE_RGB
        for foot in ("left", "right"):
            ok, found = colour_near(image, robot[foot]["px"], robot[foot]["py"], rgb)
            assert ok, f"team {robot['team']} player {robot['player']} {foot} foot pixel is {found}, not {rgb}"


def test_step_buttons_show_the_next_and_previous_frame(page, replay_server):
    open_viewer(page, replay_server.url)
    page.locator("#step-fwd").click()
    assert_shows_frame(wait_for_frame(page, 1), 1)
    page.locator("#step-fwd").click()
    assert_shows_frame(wait_for_frame(page, 2), 2)
    page.locator("#step-back").click()
    assert_shows_frame(wait_for_frame(page, 1), 1)
    page.keyboard.press("ArrowRight")
    assert_shows_frame(wait_for_frame(page, 2), 2)
    page.evaluate("window.viewer.seek(0)")
    assert page.evaluate("window.viewer.step(-1)")["frame"] == 0, "stepping back from the first frame stays there"


def test_scrubbing_shows_the_frame_at_that_sim_time(page, replay_server):
    open_viewer(page, replay_server.url)
    page.locator("#scrub").fill(str(utime_of(7) / 1e6 + 0.01))
    state = wait_for_frame(page, 7)
    assert_shows_frame(state, 7)
    assert page.locator("#clock").text_content() == "09:59", "the game state logged before frame 7"
    page.locator("#scrub").fill(str(utime_of(3) / 1e6))
    assert_shows_frame(wait_for_frame(page, 3), 3)


def test_play_runs_to_the_last_frame_and_stops(page, replay_server):
    open_viewer(page, replay_server.url)
    page.locator("#speed").select_option("4")
    page.locator("#play").click()
    page.wait_for_function("() => { const s = JSON.parse(document.getElementById('state').textContent);"
                           f" return s.frame === {FRAMES - 1} && !s.replay.playing; }}", timeout=WAIT_S * 1000)
    state = drawn(page)
    assert_shows_frame(state, FRAMES - 1)
    assert state["replay"]["speed"] == 4
    assert page.locator("#play").text_content() == "Play"


def test_screenshot(page, replay_server, tmp_path):
    """Saves a screenshot of the known log to the build folder (the tests never write to
    the source tree; docs/viewer.png is made with viewer/export, see viewer/README.md)."""
    open_viewer(page, replay_server.url)
    page.evaluate(f"window.viewer.seek({utime_of(FRAMES // 2) / 1e6})")
    shot = tmp_path / "viewer.png"
    page.screenshot(path=str(shot))
    assert Image.open(shot).size == VIEWPORT
    build = os.environ.get("TOUCHLINE_BUILD_DIR")
    if build:
        shutil.copyfile(shot, Path(build) / "viewer-test-screenshot.png")
