"""ReplayLog and ReplaySession without a browser: time lookup, the frame's game state,
statuses, sonar, match events and each robot's belief and role, the timeline in the hello, and
the play, pause, step, seek and speed commands on a fake clock."""
import asyncio

import lcm
import pytest

from known_log import (COVARIANCES, EVENTS, FALL_US, FRAMES, GOAL_US, ROBOTS, ROLE_EVERY_FRAMES, ROLES, SENSE_FRAMES,
                       belief_at, known_messages, sonar_at, utime_of)
from touchline_viewer.replay import ReplaySession
from touchline_viewer.replay_log import ReplayLog


class FakeClock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


@pytest.fixture(scope="module")
def log(known_log):
    return ReplayLog.load(known_log)


def test_the_log_is_indexed_by_sim_time(log):
    assert (log.count, log.t0, log.t1) == (FRAMES, utime_of(0) / 1e6, utime_of(FRAMES - 1) / 1e6)
    assert log.index_at(0) == 0, "before the first frame: the first frame"
    assert log.index_at(utime_of(5) / 1e6) == 5
    assert log.index_at(utime_of(5) / 1e6 + 0.02) == 5, "between frames: the last one at or before"
    assert log.index_at(1e6) == FRAMES - 1


def test_a_frame_carries_the_game_state_and_statuses_logged_up_to_it(log):
    assert log.frame(5)["game"]["secs_remaining"] == 600
    assert log.frame(6)["game"]["secs_remaining"] == 599
    statuses = log.frame(0)["status"]
    assert [(s["team"], s["player"]) for s in statuses] == [spec[:2] for spec in ROBOTS]
    assert [s["state"] for s in statuses if not s["frames_missed"] == 0] == ["TIMED_OUT"]


def test_a_frame_carries_the_sonar_of_its_own_sense_frame(log):
    for k in range(FRAMES):
        sense = log.frame(k)["sense"]
        if k not in SENSE_FRAMES:
            assert sense is None, "no TL_SENSE for this frame: none, not the previous frame's"
            continue
        assert sense["frame"] == k
        assert [(r["team"], r["player"], tuple(r["sonar"])) for r in sense["robots"]] == \
            [(spec[0], spec[1], sonar_at(spec[0], spec[1], k)) for spec in ROBOTS]


def test_a_frame_carries_the_latest_match_events_up_to_it(log):
    kinds = {0: "STATE_CHANGE", 1: "GOAL", 2: "PENALTY", 4: "FALL"}
    assert log.frame(FRAMES - 1)["events"] == [{"utime": u, "kind": kinds[kind], "team": team, "player": player,
                                                "text": text} for u, kind, team, player, text in EVENTS]
    assert [e["text"] for e in log.frame(5)["events"]] == ["PLAYING", "pushing"], "the fall comes in frame 6"


def test_a_frame_carries_each_robot_s_belief_from_its_act(log):
    for k in (0, 4, FRAMES - 1):
        beliefs = log.frame(k)["beliefs"]
        assert [(b["team"], b["player"]) for b in beliefs] == sorted(COVARIANCES), "robots without acts: none"
        for b in beliefs:
            want = belief_at(b["team"], b["player"], k)
            assert b["frame"] == k
            assert b["pose"] == pytest.approx(list(want["pose"]), abs=0.06)
            assert b["cov"] == list(want["cov"]) and b["ball"] == pytest.approx(list(want["ball"]), abs=0.06)
            assert b["ball_lost"] == want["ball_lost"]


def test_a_role_lasts_from_one_team_message_to_the_next(log):
    """Messages come every ROLE_EVERY_FRAMES frames; the frames between show the last one's role."""
    for k in range(FRAMES):
        roles = {(b["team"], b["player"]): b["role"] for b in log.frame(k)["beliefs"]}
        assert roles == {key: ROLES.get(key) for key in COVARIANCES}, f"frame {k}"
    assert ROLE_EVERY_FRAMES > 1


def test_a_role_is_forgotten_when_its_message_is_stale(tmp_path):
    """Acts every 10 frames, only the first with a team message: its role lasts 60 frames (2 s)."""
    path = tmp_path / "stale.lcmlog"
    writer = lcm.EventLog(str(path), "w", overwrite=True)
    for utime, channel, message in known_messages():
        if channel.startswith("TL_ACT_"):
            message.frame *= 10
            if message.frame > 0:
                message.team_message, message.team_message_size = b"", 0
        writer.write_event(utime, channel, message.encode())
    writer.close()
    stale = ReplayLog.load(path)
    assert {b["role"] for b in stale.beliefs_at(60)} == {"goalie", "striker", "defender", "midfielder", None}
    assert {b["role"] for b in stale.beliefs_at(70)} == {None}, "a message older than 2 s names no role"
    assert len(stale.beliefs_at(140)) == len(COVARIANCES), "the act of frame 110 is 30 frames old: still believed"
    assert stale.beliefs_at(141) == [], "an act older than 1 s is no belief"


def test_the_hello_carries_the_timeline(log):
    marks = ReplaySession(log, send=None).hello()["timeline"]
    assert [(m["kind"], m["t"]) for m in marks] == [("state", 0), ("penalty", 0), ("fall", FALL_US / 1e6),
                                                    ("goal", GOAL_US / 1e6)]


def test_seek_after_shows_the_first_frame_at_or_after(log):
    session = ReplaySession(log, send=None, clock=FakeClock())
    session.apply({"cmd": "seek", "t": FALL_US / 1e6})
    assert session.index == 5, "the last frame at or before the fall"
    session.apply({"cmd": "seek", "t": FALL_US / 1e6, "after": True})
    assert session.index == 6, "a marker shows its effect: the first frame after it"
    session.apply({"cmd": "seek", "t": 1e6, "after": True})
    assert session.index == FRAMES - 1


def test_step_seek_and_speed(log):
    session = ReplaySession(log, send=None, clock=FakeClock())
    session.apply({"cmd": "step", "n": -1})
    assert session.index == 0, "clamped at the first frame"
    session.apply({"cmd": "step", "n": 3})
    assert session.index == 3
    session.apply({"cmd": "seek", "t": utime_of(9) / 1e6})
    assert session.index == 9
    session.apply({"cmd": "step", "n": 50})
    assert session.index == FRAMES - 1, "clamped at the last frame"
    session.apply({"cmd": "speed", "x": 7})
    assert session.speed == 8.0, "snapped to the nearest offered speed"
    for bad in ({"cmd": "seek"}, {"cmd": "seek", "t": "soon"}, {"cmd": "step", "n": None}, {"cmd": "dance"}):
        session.apply(bad)
    assert (session.index, session.speed) == (FRAMES - 1, 8.0), "malformed commands change nothing"


def test_play_follows_the_clock_times_speed_and_stops_at_the_end(log):
    clock = FakeClock()
    session = ReplaySession(log, send=None, clock=clock)
    session.apply({"cmd": "speed", "x": 0.5})
    session.apply({"cmd": "play"})
    clock.now += 0.2  # 0.1 s of sim time at half speed: 3 frames on
    assert session._advance() and session.index == 3 and session.playing
    clock.now += 10
    session._advance()
    assert (session.index, session.playing) == (FRAMES - 1, False)
    session.apply({"cmd": "play"})
    assert (session.index, session.playing) == (0, True), "play at the end starts over"
    session.apply({"cmd": "pause"})
    clock.now += 1
    assert session.index == 0 and not session.playing


def test_every_command_is_answered_by_a_frame_that_acks_it(log):
    async def scenario():
        sent = []

        async def send(frame):
            sent.append(frame)

        session = ReplaySession(log, send)
        task = asyncio.create_task(session.run())
        session.commands.put_nowait({"cmd": "step", "n": 2, "seq": 1})
        session.commands.put_nowait({"cmd": "nonsense", "seq": 2})
        while len(sent) < 3:
            await asyncio.sleep(0.01)
        task.cancel()
        return sent

    sent = asyncio.run(asyncio.wait_for(scenario(), 10))
    assert [(f["ack"], f["replay"]["index"]) for f in sent] == [(None, 0), (1, 2), (2, 2)]
    assert sent[1]["truth"]["frame"] == 2
