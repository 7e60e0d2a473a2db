"""The page's layers over the truth, in headless Chromium replaying the known log: each robot's
role, its belief (pose, uncertainty ellipse, ball) beside the truth and the toggle that hides
it, the timeline's markers and the click that jumps to one, the legend, and the whole canvas
against a committed reference image (tests/viewer/reference/, compared with a tolerance).

TOUCHLINE_UPDATE_VIEWER_REFERENCE=1 rewrites the reference image (after a change to the
drawing that is meant; look at it before committing it)."""
import io
import math
import os

import numpy as np
import pytest
from PIL import Image, ImageChops

from conftest import ROOT, WAIT_S
from known_log import COVARIANCES, FALL_US, FRAMES, GOAL_US, ROBOTS, ROLES, belief_at, utime_of
from test_replay_page import (TEAM_RGB, assert_drawn_at, colour_near, drawn, expected_pixel, open_viewer, screenshot,
                              wait_for_frame)

BELIEF_RGB = {0: (0x8F, 0xB0, 0xFF), 1: (0xFF, 0x9A, 0x9D)}  # light tints of the team colours
MARKER_RGB = {"penalty": (0xFF, 0xD2, 0x1F), "fall": (0xFF, 0x4F, 0xD8)}
SIGMAS = 2  # the ellipse's half-axes: two standard deviations
REFERENCE = ROOT / "tests" / "viewer" / "reference" / "known_frame6.png"
REFERENCE_SCALE = 4  # the reference is the canvas at a quarter of its size: small, and blind to sub-pixel text
# How far a screenshot may be from the reference: the mean difference per channel (0-255), and
# the share of pixels off by more than PIXEL_OFF in some channel. Hiding the beliefs alone
# breaks both (asserted below), so the comparison can fail.
MEAN_TOLERANCE, PIXEL_OFF, OFF_SHARE_TOLERANCE = 0.2, 48, 0.001


def robots_by_key(state: dict) -> dict:
    return {(r["team"], r["player"]): r for r in state["robots"]}


def test_each_robot_shows_the_role_its_team_message_names(page, replay_server):
    state = open_viewer(page, replay_server.url)
    robots = robots_by_key(state)
    for spec in ROBOTS:
        role = robots[spec[:2]]["role"]
        assert (role["text"] if role else None) == ROLES.get(spec[:2]), f"robot {spec[:2]}"
    image = screenshot(page)
    for key, name in ROLES.items():
        role = robots[key]["role"]
        # the label's white letters: some pixel of its middle row, across its width, is white
        half = 3 * len(name)
        row = [image.getpixel((round(role["px"]) + dx, round(role["py"]))) for dx in range(-half, half + 1)]
        assert any(min(p[:3]) >= 230 for p in row), f"no white letter in {key}'s role label"


def ellipse_inside_point(state: dict, belief: dict, along: float) -> tuple:
    """A pixel `along` of the way from the believed pose to the ellipse's end on its major axis."""
    e, pose = belief["ellipse"], belief["pose"]
    r = along * e["major_px"]
    return pose["px"] + r * math.cos(e["angle_rad"]), pose["py"] - r * math.sin(e["angle_rad"])


def ring_pixels_in(image: Image.Image, belief: dict) -> int:
    """How many of 24 points round the believed pose's ring have the belief's colour."""
    pose, rgb = belief["pose"], BELIEF_RGB[belief["team"]]
    points = [(pose["px"] + pose["ring_px"] * math.cos(a), pose["py"] - pose["ring_px"] * math.sin(a))
              for a in (k * math.pi / 12 for k in range(24))]
    return sum(colour_near(image, x, y, rgb, tolerance=40)[0] for x, y in points)


def test_each_belief_is_drawn_where_the_act_says_with_its_ellipse(page, replay_server):
    state = open_viewer(page, replay_server.url)
    assert state["show_beliefs"] is True
    beliefs = {(b["team"], b["player"]): b for b in state["beliefs"]}
    assert sorted(beliefs) == sorted(COVARIANCES)
    scale = state["scale_px_per_mm"]
    for key, b in beliefs.items():
        want = belief_at(*key, 0)
        assert b["colour"].upper() == "#%02X%02X%02X" % BELIEF_RGB[key[0]]
        assert_drawn_at(state, b["pose"], want["pose"])
        assert_drawn_at(state, b["ball"], want["ball"])
        xx, xy, yy = want["cov"]
        if xx == yy == 0:
            assert "ellipse" not in b, "perfect localisation: no ellipse"
            continue
        mid, diff = (xx + yy) / 2, math.hypot((xx - yy) / 2, xy)
        assert b["ellipse"]["major_px"] == pytest.approx(SIGMAS * math.sqrt(mid + diff) * scale, abs=0.06)
        assert b["ellipse"]["minor_px"] == pytest.approx(SIGMAS * math.sqrt(mid - diff) * scale, abs=0.06)
    assert beliefs[(1, 1)]["ellipse"]["angle_rad"] == pytest.approx(math.pi / 4, abs=1e-3), "xy > 0: tilted 45 deg"
    assert beliefs[(1, 2)]["ellipse"]["angle_rad"] == pytest.approx(math.pi / 2, abs=1e-3), "yy > xx: along y"
    assert beliefs[(1, 2)]["ball"]["alpha"] < beliefs[(0, 1)]["ball"]["alpha"] == 1, "a ball not seen lately fades"


def test_the_toggle_hides_and_shows_the_beliefs(page, replay_server):
    state = open_viewer(page, replay_server.url)
    goalie = next(b for b in state["beliefs"] if (b["team"], b["player"]) == (0, 1))
    inside = tuple(map(round, ellipse_inside_point(state, goalie, 0.8)))  # clear of the ring and the robot
    image = screenshot(page)
    shown = image.getpixel(inside)[:3]
    assert ring_pixels_in(image, goalie) >= 3, "the dashed ring of the believed pose, in the belief colour"
    page.locator("#beliefs").click()
    hidden_state = drawn(page)
    assert hidden_state["show_beliefs"] is False and hidden_state["beliefs"] == []
    image = screenshot(page)
    hidden = image.getpixel(inside)[:3]
    assert ring_pixels_in(image, goalie) == 0, "no ring with the beliefs hidden"
    assert shown[2] > hidden[2] + 15, f"the ellipse tints what is under it with team 0's blue ({shown} over {hidden})"
    page.keyboard.press("b")
    assert drawn(page)["show_beliefs"] is True, "the b key shows them again"
    assert page.locator("#beliefs").is_checked()
    assert screenshot(page).getpixel(inside)[:3] == shown


def test_the_timeline_marks_goals_penalties_falls_and_states(page, replay_server):
    state = open_viewer(page, replay_server.url)
    strip = state["timeline"]
    marks = {m["kind"]: m for m in strip["markers"]}
    assert sorted(marks) == ["fall", "goal", "penalty", "state"]
    assert marks["goal"]["t"] == pytest.approx(GOAL_US / 1e6) and marks["fall"]["t"] == pytest.approx(FALL_US / 1e6)
    t0, t1 = utime_of(0) / 1e6, utime_of(FRAMES - 1) / 1e6
    assert marks["goal"]["x"] > marks["fall"]["x"] > marks["penalty"]["x"], "left to right in time"
    assert marks["fall"]["x"] == pytest.approx(6 + (FALL_US / 1e6 - t0) / (t1 - t0) * (strip["width"] - 12), abs=0.5)
    assert strip["playhead_x"] == pytest.approx(6, abs=0.06), "the playhead at the first frame"
    strip = page.evaluate(f"window.viewer.seek({t1})")["timeline"]  # the playhead off the markers
    assert strip["playhead_x"] == pytest.approx(strip["width"] - 6, abs=0.06), "the playhead at the last frame"
    image = Image.open(io.BytesIO(page.locator("#timeline").screenshot())).convert("RGB")
    h = strip["height"]
    for kind, y in (("goal", h * 0.5), ("penalty", h * 0.3), ("fall", h * 0.75)):
        rgb = TEAM_RGB[0] if kind == "goal" else MARKER_RGB[kind]
        ok, found = colour_near(image, marks[kind]["x"], y, rgb)
        assert ok, f"the {kind} marker is {found}, not {rgb}"


def test_a_click_on_a_marker_jumps_to_its_effect_and_elsewhere_to_that_time(page, replay_server):
    state = open_viewer(page, replay_server.url)
    strip, box = state["timeline"], page.locator("#timeline").bounding_box()
    fall = next(m for m in strip["markers"] if m["kind"] == "fall")
    page.mouse.click(box["x"] + fall["x"] + 2, box["y"] + strip["height"] * 0.75)  # within the snap
    state = wait_for_frame(page, 6)
    assert robots_by_key(state)[(0, 2)]["fallen"], "the first frame after the fall shows it"
    goal = next(m for m in strip["markers"] if m["kind"] == "goal")
    page.mouse.click(box["x"] + goal["x"], box["y"] + 5)
    assert wait_for_frame(page, 9)["game"]["secs_remaining"] == 599, "the frame after the goal"
    span_us = utime_of(FRAMES - 1) - utime_of(0)
    x_of = lambda utime: 6 + (utime - utime_of(0)) / span_us * (strip["width"] - 12)  # noqa: E731
    page.mouse.click(box["x"] + x_of(utime_of(3) + 5000), box["y"] + strip["height"] / 2)  # no marker near
    state = wait_for_frame(page, 3)
    assert state["timeline"]["playhead_x"] == pytest.approx(x_of(utime_of(3)), abs=0.06)


def test_the_legend_names_every_mark(page, replay_server):
    open_viewer(page, replay_server.url)
    legend = page.locator("#legend")
    assert legend.is_visible()
    text = legend.text_content()
    for words in ("team 0", "penalised", "inactive", "heading", "role", "chest LED", "camera", "sonar", "fallen",
                  "ball", "believed pose", "ellipse", "believed ball", "goal", "penalty", "fall", "game state"):
        assert words in text, f"the legend lacks {words!r}"


def canvas_at_reference_size(page) -> Image.Image:
    image = screenshot(page)
    return image.resize((image.width // REFERENCE_SCALE, image.height // REFERENCE_SCALE), Image.BOX)


def difference(a: Image.Image, b: Image.Image) -> tuple:
    """(mean difference per channel, share of pixels off by more than PIXEL_OFF in some channel)."""
    assert a.size == b.size, f"size {a.size}, the reference's {b.size}"
    diff = np.asarray(ImageChops.difference(a, b), dtype=np.float64)
    return float(diff.mean()), float((diff.max(axis=2) > PIXEL_OFF).mean())


def test_the_canvas_matches_the_reference_image(page, replay_server):
    open_viewer(page, replay_server.url)
    page.evaluate(f"window.viewer.seek({utime_of(6) / 1e6})")
    shot = canvas_at_reference_size(page)
    if os.environ.get("TOUCHLINE_UPDATE_VIEWER_REFERENCE"):
        REFERENCE.parent.mkdir(exist_ok=True)
        shot.save(REFERENCE, optimize=True)
    reference = Image.open(REFERENCE).convert("RGB")
    mean, off = difference(shot, reference)
    assert mean <= MEAN_TOLERANCE and off <= OFF_SHARE_TOLERANCE, \
        f"the canvas differs from {REFERENCE.name}: mean {mean:.2f}, {off:.2%} of pixels off"
    page.evaluate("window.viewer.setBeliefs(false)")
    mean, off = difference(canvas_at_reference_size(page), reference)
    assert mean > MEAN_TOLERANCE or off > OFF_SHARE_TOLERANCE, \
        f"the comparison must see the beliefs go (mean {mean:.2f}, {off:.2%} off)"
