"""The page in headless Chromium, replaying the known log: the field, robots and ball drawn
where and as large as the log says (page state and pixels), chest LEDs, penalised and fallen
badges, sonar bars and camera cones with the match's own sizes, match events, step, scrub and
play, and the README's screenshot."""
import io
import json
import math
import os
import shutil
from pathlib import Path

import pytest
from PIL import Image

from conftest import ROOT, VIEWPORT, WAIT_S
from known_log import (EVENTS, FRAMES, LEDS, MATCH, ROBOTS, SCORE, SENSE_FRAMES, ball_at, camera_range_mm, robot_at,
                       sonar_at, utime_of)

TEAM_RGB = {0: (0x1E, 0x63, 0xFF), 1: (0xE8, 0x23, 0x2A)}
PENALISED_RGB = {0: (0x55, 0x77, 0xC5), 1: (0xBA, 0x57, 0x5B)}
INACTIVE_RGB = (0x8C, 0x8C, 0x8C)
BALL_RGB = (0xFF, 0x7F, 0x00)
BADGE_RGB = {"P": (0xFF, 0xD2, 0x1F), "F": (0xFF, 0x4F, 0xD8)}
SONAR_RGB = (0x00, 0xE5, 0xFF)
SONAR_RANGE_MM, SONAR_HALF_WIDTH_MM = MATCH["sonar_range_mm"], MATCH["sonar_half_width_mm"]


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
    span_x, span_y = (MATCH[f"field_{side}_mm"] + 2 * MATCH["border_mm"] for side in ("length", "width"))
    s = min(w / span_x, h / span_y)
    return w / 2 + x * s, h / 2 - y * s


def assert_drawn_at(state: dict, place: dict, pose) -> None:
    assert place["x"] == pytest.approx(pose[0], abs=0.06) and place["y"] == pytest.approx(pose[1], abs=0.06)
    px, py = expected_pixel(state, pose[0], pose[1])
    assert place["px"] == pytest.approx(px, abs=0.06) and place["py"] == pytest.approx(py, abs=0.06)


def ahead_of(body, ahead_mm: float, left_mm: float) -> tuple:
    """A point in the robot's frame (ahead, + left) in field mm."""
    x, y, th = body
    return (x + ahead_mm * math.cos(th) - left_mm * math.sin(th), y + ahead_mm * math.sin(th) + left_mm * math.cos(th))


def assert_sonar_drawn(state: dict, got: dict, want: dict, k: int) -> None:
    if k not in SENSE_FRAMES:
        assert got["sonar"] is None, "a frame without its own TL_SENSE shows no sonar"
        return
    readings = dict(zip(("left", "right"), sonar_at(want["team"], want["player"], k)))
    assert (got["sonar"]["left"], got["sonar"]["right"]) == (readings["left"], readings["right"])
    bars = {bar["side"]: bar for bar in got["sonar"]["bars"]}
    assert set(bars) == {side for side, reading in readings.items() if reading < 1}, "a reading of 1 draws nothing"
    for side, bar in bars.items():
        length = readings[side] * SONAR_RANGE_MM
        assert bar["length_mm"] == pytest.approx(length, abs=0.06)
        half = SONAR_HALF_WIDTH_MM / 2 if side == "left" else -SONAR_HALF_WIDTH_MM / 2
        assert_drawn_at(state, bar["end"], ahead_of(want["body"], length, half))


def assert_shows_frame(state: dict, k: int) -> None:
    assert (state["frame"], state["utime"]) == (k, utime_of(k))
    assert_drawn_at(state, state["ball"], ball_at(k))
    robots = {(r["team"], r["player"]): r for r in state["robots"]}
    assert len(robots) == len(ROBOTS)
    for spec in ROBOTS:
        want, got = robot_at(spec, k), robots[spec[:2]]
        assert (got["active"], got["penalised"], got["fallen"]) == (want["active"], want["penalised"], want["fallen"])
        assert [b["text"] for b in got["badges"]] == ["P"] * want["penalised"] + ["F"] * want["fallen"]
        for part in ("body", "left", "right"):
            assert_drawn_at(state, got[part], want[part])
        assert_sonar_drawn(state, got, want, k)
        reach_px = camera_range_mm(want["head"][1]) * state["scale_px_per_mm"]
        assert got["camera"]["range_px"] == pytest.approx(reach_px, abs=0.06), "the match's camera reach"
        led = LEDS.get(spec[:2])
        assert got["led"] == ({"colour": "#%06x" % led, "radius_px": got["led"]["radius_px"]} if led else None)
    assert [e["text"] for e in state["events"]] == [e[4] for e in EVENTS if e[0] <= utime_of(k)]


def screenshot(page) -> Image.Image:
    return Image.open(io.BytesIO(page.locator("#field").screenshot())).convert("RGB")


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
    image = screenshot(page)
    assert image.size == (state["canvas"]["width"], state["canvas"]["height"])
    ok, found = colour_near(image, state["ball"]["px"], state["ball"]["py"], BALL_RGB)
    assert ok, f"ball pixel is {found}"
    for robot in state["robots"]:
        rgb = (PENALISED_RGB if robot["penalised"] else TEAM_RGB)[robot["team"]] if robot["active"] else INACTIVE_RGB
        body = robot["body"]
        for foot in ("left", "right"):
            # the foot's outer half, 20 mm out from its centre: the chest LED's disc on the body
            # centre may reach the centre of a foot at this scale
            f = robot[foot]
            out = 20 / math.hypot(f["x"] - body["x"], f["y"] - body["y"])
            x, y = f["x"] + (f["x"] - body["x"]) * out, f["y"] + (f["y"] - body["y"]) * out
            ok, found = colour_near(image, *expected_pixel(state, x, y), rgb)
            assert ok, f"team {robot['team']} player {robot['player']} {foot} foot pixel is {found}, not {rgb}"


def test_the_field_is_the_match_s_own(page, replay_server):
    state = open_viewer(page, replay_server.url)
    assert state["field"]["length_mm"] == MATCH["field_length_mm"]
    assert state["field"]["width_mm"] == MATCH["field_width_mm"]
    image = screenshot(page)
    for x, y in ((MATCH["field_length_mm"] / 2 - 25, 0), (-MATCH["field_length_mm"] / 2 + 25, 1000)):
        ok, found = colour_near(image, *expected_pixel(state, x, y), (0xF4, 0xF4, 0xF4), tolerance=40)
        assert ok, f"the goal line at x = {x} mm is {found}, not white"


def test_chest_leds_are_drawn_on_the_body(page, replay_server):
    state = open_viewer(page, replay_server.url)
    image = screenshot(page)
    robots = {(r["team"], r["player"]): r for r in state["robots"]}
    for key, rgb in LEDS.items():
        body = robots[key]["body"]
        ok, found = colour_near(image, body["px"], body["py"] + 1, tuple(rgb.to_bytes(3, "big")))
        assert ok, f"{key}'s chest LED is {found}, not #{rgb:06x}"


def test_badges_and_sonar_bars_have_their_colours(page, replay_server):
    open_viewer(page, replay_server.url)
    k = 7
    state = page.evaluate(f"window.viewer.seek({utime_of(k) / 1e6})")
    assert_shows_frame(state, k)
    image = screenshot(page)
    robots = {(r["team"], r["player"]): r for r in state["robots"]}
    for key, text in (((1, 4), "P"), ((0, 2), "F")):
        [badge] = robots[key]["badges"]
        assert (badge["text"], badge["colour"].upper()) == (text, "#%02X%02X%02X" % BADGE_RGB[text])
        ok, found = colour_near(image, badge["px"] - badge["radius_px"] + 2, badge["py"], BADGE_RGB[text])
        assert ok, f"the {text} badge of {key} is {found} beside its letter"
    body = robot_at(ROBOTS[0], k)["body"]  # (0, 1): 0.6 on the left, nothing on the right
    ok, found = colour_near(image, *expected_pixel(state, *ahead_of(body, 450, 50)), SONAR_RGB)
    assert ok, f"the left sonar bar is {found}"
    ok, found = colour_near(image, *expected_pixel(state, *ahead_of(body, 450, -50)), SONAR_RGB)
    assert not ok, "no bar on the right: it reads 1"


def test_hud_lists_the_latest_match_events(page, replay_server):
    open_viewer(page, replay_server.url)
    events = page.locator("#events li")
    assert events.all_text_contents() == ["0.0 s STATE_CHANGE: PLAYING", "0.0 s PENALTY Red 4: pushing"]
    page.evaluate(f"window.viewer.seek({utime_of(6) / 1e6})")
    assert events.all_text_contents()[-1] == "0.2 s FALL Blue 2: fell"


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
