"""The launcher's match watcher on its own: what it keeps from the bus, and that no message,
however malformed, ends it."""
import sys
import time

import lcm
import pytest
from conftest import LCM_URL, ROOT

sys.path.insert(0, str(ROOT / "tools"))
from match_checks import MatchPlan  # noqa: E402
from match_watch import MatchWatch  # noqa: E402
from touchline import game_state_t, match_config_t, match_event_t, robot_status_t  # noqa: E402


@pytest.fixture
def watch():
    w = MatchWatch(LCM_URL, show_bar=False, team_size=2)
    yield w
    w.stop()


def wait_until(condition, timeout=30) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "the watcher never got there"
        time.sleep(0.01)  # polling the watcher's state, not hiding a race


def game(score, utime=5_000_000, state=game_state_t.PLAYING, set_play=game_state_t.SET_PLAY_NONE, set_play_team=-1):
    msg = game_state_t()
    msg.utime, msg.state, msg.score = utime, state, score
    msg.set_play, msg.set_play_team = set_play, set_play_team
    return msg.encode()


def event(kind, team, player=0, utime=1_000_000, text=""):
    msg = match_event_t()
    msg.utime, msg.kind, msg.team, msg.player, msg.text = utime, kind, team, player, text
    return msg.encode()


def status(team, player, state, detail="", utime=2_000_000):
    msg = robot_status_t()
    msg.utime, msg.team, msg.player, msg.state, msg.detail = utime, team, player, state, detail
    return msg.encode()


def match_config(length_mm=7000.0, version=match_config_t.TYPES_VERSION, team_size=3):
    msg = match_config_t()
    msg.types_version, msg.team_size, msg.duration_s = version, team_size, 60.0
    msg.field_length_mm, msg.field_width_mm = length_mm, 4000.0
    return msg.encode()


def test_the_match_is_taken_from_its_tl_match_and_an_unusable_one_is_refused(watch):
    bus = lcm.LCM(LCM_URL)
    bus.publish("TL_MATCH", match_config(version=match_config_t.TYPES_VERSION + 1))  # other types
    bus.publish("TL_MATCH", match_config(length_mm=float("nan")))
    bus.publish("TL_MATCH", match_config(team_size=8))
    bus.publish("TL_MATCH", match_config(length_mm=7000.0))
    bus.publish("TL_MATCH", match_config(length_mm=9000.0))  # only the first counts: the world repeats it
    bus.publish("TL_STATUS", status(0, 3, robot_status_t.JOINED))  # player 3: in a team of 3 now
    wait_until(lambda: (0, 3) in watch.status)
    assert watch.malformed["TL_MATCH"] == 3 and "types version" not in watch.last_malformed
    assert watch.match.field_length_mm == 7000.0 and watch.match.team_size == 3
    assert watch.malformed["TL_STATUS"] == 0


def test_malformed_messages_are_counted_per_channel_and_skipped(watch):
    bus = lcm.LCM(LCM_URL)
    bus.publish("TL_EVENT", b"\x01\x02\x03")                        # not an LCM message of the type
    bus.publish("TL_EVENT", event(match_event_t.GOAL, team=5))      # no team 5
    bus.publish("TL_STATUS", status(0, 3, robot_status_t.JOINED))   # player 3 in a team of 2
    bus.publish("TL_STATUS", status(0, 1, 42))                      # no state 42
    bus.publish("TL_GAME", game([2, 1])[:-1])                       # truncated
    bus.publish("TL_GAME", game([-1, 0]))                           # a negative score
    bus.publish("TL_GAME", game([0, 0], state=6))                   # no state 6
    bus.publish("TL_GAME", game([0, 0], set_play=game_state_t.SET_PLAY_KICK_IN, set_play_team=2))  # no team 2
    bus.publish("TL_GAME", game([0, 0], state=game_state_t.STANDBY))
    bus.publish("TL_GAME", game([1, 0], set_play=game_state_t.SET_PLAY_CORNER_KICK, set_play_team=1))
    bus.publish("TL_EVENT", event(match_event_t.GOAL, team=0))
    bus.publish("TL_STATUS", status(1, 2, robot_status_t.TIMED_OUT, "no answer within 300 ms"))
    bus.publish("TL_GAME", game([2, 1]))
    wait_until(lambda: watch.score == (2, 1))
    assert watch.error is None
    assert watch.malformed == {"TL_MATCH": 0, "TL_GAME": 4, "TL_STATUS": 2, "TL_EVENT": 2}
    assert watch.timed_out(1, 2) and not watch.timed_out(0, 1)
    assert watch.events == [(2.0, "team 1 player 2 no answer within 300 ms")]
    assert watch.kicked_off and watch.sim_s == 5.0


def test_each_goal_grows_the_progress_total_by_its_stoppage_even_when_its_goal_event_is_lost():
    # The bus drops packets under load: the score, which every TL_GAME repeats, counts the goals.
    plan = MatchPlan(planned_s=40.0, goal_stoppage_s=3.0, duration_s=60.0)  # TL_MATCH: 60 s
    watch = MatchWatch(LCM_URL, team_size=2, plan=plan, progress="lines")
    try:
        bus = lcm.LCM(LCM_URL)
        bus.publish("TL_MATCH", match_config(team_size=2))
        wait_until(lambda: watch.progress is not None)
        bus.publish("TL_GAME", game([1, 0], utime=20_000_000))   # its GOAL event never came
        bus.publish("TL_EVENT", event(match_event_t.GOAL, team=1, utime=30_000_000))
        bus.publish("TL_GAME", game([1, 1], utime=30_000_000))   # after its GOAL event: counted once
        bus.publish("TL_GAME", game([1, 1], utime=31_000_000))   # the world repeats the game
        bus.publish("TL_EVENT", event(match_event_t.GAME_STUCK, team=0, utime=40_000_000))
        bus.publish("TL_GAME", game([1, 1], utime=41_000_000))
        wait_until(lambda: watch.sim_s == 41.0)
        assert watch.progress.total == 40.0 + 3 * 3.0
    finally:
        watch.stop()


def test_a_state_the_world_repeats_is_one_event(watch):
    bus = lcm.LCM(LCM_URL)
    bus.publish("TL_STATUS", status(0, 1, robot_status_t.TIMED_OUT, "no answer within 300 ms", utime=1_000_000))
    bus.publish("TL_STATUS", status(0, 1, robot_status_t.TIMED_OUT, "match over", utime=9_000_000))
    bus.publish("TL_GAME", game([0, 0], utime=9_000_000))
    wait_until(lambda: watch.kicked_off)
    assert watch.events == [(1.0, "team 0 player 1 no answer within 300 ms")]


def test_a_failing_watcher_says_why_instead_of_ending_silently(watch):
    class Broken(dict):
        def __setitem__(self, key, value):
            raise RuntimeError("bookkeeping broke")

    watch.status = Broken()  # a fault in the watcher's own code, not in a message
    lcm.LCM(LCM_URL).publish("TL_STATUS", status(0, 1, robot_status_t.ACTIVE))
    wait_until(lambda: watch.error is not None)
    assert watch.error == "RuntimeError: bookkeeping broke"
