"""tools/spy: without a display one line pointing to --text; tools/spy --text shows a running
match's bus in the terminal: every channel with its rate and last message, robots and frame."""
import hashlib
import hmac
import os
import re
import subprocess
import time

from conftest import ROOT, Launch

SPY = str(ROOT / "tools" / "spy")
# 1 v 1, paced to the wall clock so the rates are the match's own (30 frames a second).
PACED = ("--team-size", 1, "--behaviour", "goto", "--mode", "realtime", "--duration", 100000, "--no-log")


def spy(*args, env_drop=(), timeout=60):
    # Not the launcher's secret (a fresh one per match, never shown): the tags go unverified.
    env = {k: v for k, v in os.environ.items() if k not in (*env_drop, "TOUCHLINE_MATCH_SECRET")}
    env["COLUMNS"] = "220"  # every column of the table, unwrapped
    return subprocess.run([SPY, *map(str, args)], capture_output=True, text=True, timeout=timeout, env=env)


def test_without_a_display_it_says_so_in_one_line_and_offers_the_text_view():
    result = spy(env_drop=("DISPLAY", "WAYLAND_DISPLAY"))
    assert result.returncode == 2 and result.stdout == ""
    [line] = result.stderr.splitlines()
    assert "no display" in line and "tools/spy --text" in line, line


def test_an_empty_bus_is_one_line_and_exit_code_1():
    result = spy("--text", "--once", "--duration", 0.5)
    assert result.returncode == 1
    assert result.stderr.splitlines()[-1].startswith("tools/spy: nothing heard on udpm://"), result.stderr


def test_the_text_view_shows_channels_rates_last_messages_robots_and_frame():
    match = Launch(*PACED)
    match.wait_for_line("launch: kick-off,")
    result = spy("--text", "--once", "--duration", 2)
    assert result.returncode == 0, result.stderr
    out = result.stdout
    for channel in ("TL_MATCH", "TL_SENSE", "TL_TRUTH", "TL_GAME", "TL_ACT_0_1", "TL_ACT_1_1", "TL_BLACKBOARD_0_1"):
        assert re.search(rf"\b{channel}\b", out), f"{channel} missing:\n{out}"
    rate = float(re.search(r"TL_SENSE\s*\W\s*\d+\s*\W\s*([\d.]+)", out).group(1))
    assert 20 <= rate <= 40, f"TL_SENSE at {rate} Hz in a match paced at 30 frames a second:\n{out}"
    assert re.search(r"TL_SENSE.*frame=\d+", out), "the last sense_t decoded"
    assert re.search(r"frame \d+ \([\d.]+ s simulated\)", out), out
    assert re.search(r"\b0/1\b.*\bactive\b", out) and re.search(r"\b1/1\b.*\bactive\b", out), out
    assert "undecoded" not in out, out


def test_with_the_match_secret_forged_messages_are_counted_and_not_shown():
    import lcm
    from touchline import game_state_t

    key = bytes(range(32))
    env = {**os.environ, "TOUCHLINE_MATCH_SECRET": key.hex(), "COLUMNS": "220"}
    viewer = subprocess.Popen([SPY, "--text", "--once", "--duration", "3"], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, env=env)
    bus = lcm.LCM("udpm://239.255.76.67:7667?ttl=0")
    game = game_state_t()
    game.state, game.score = game_state_t.PLAYING, [2, 1]
    sealed = game.encode() + hmac.new(key, b"TL_GAME\0" + game.encode(), hashlib.sha256).digest()
    forged = game_state_t()
    forged.score = [9, 9]
    deadline = time.monotonic() + 2
    while time.monotonic() < deadline:  # the spy subscribes some time after it starts: keep sending
        bus.publish("TL_GAME", sealed)
        bus.publish("TL_GAME", forged.encode() + bytes(32))  # a tag, but not the match's
        time.sleep(0.05)
    out, err = viewer.communicate(timeout=30)
    assert viewer.returncode == 0, err
    assert "tags checked with the match secret" in out
    row = next(line for line in out.splitlines() if "TL_GAME" in line)
    cells = [cell.strip() for cell in row.split("│")[1:-1]]  # channel, msgs, Hz, bytes, forged, last message
    count, forged_count = int(cells[1]), int(cells[4])
    assert count > 0 and abs(2 * forged_count - count) <= 1, row  # one of each pair (the spy may start mid-pair)
    assert "score=[2,1]" in row and "[9,9]" not in out, out
    assert "game PLAYING 2:1" in out, out
