"""The launcher under injected faults, one test per promise in the README (Reliability):
a shim killed (restarted or not), a shim stopped and continued, the world killed, the
launcher sent SIGTERM, Ctrl-C or SIGKILL, and malformed messages on the channels it watches.

Matches are 1 v 1 and paced to the wall clock (realtime mode) where a fault must land
during the match: in lockstep a short match could end before it.
"""
import json
import os
import signal

import pytest
from conftest import LCM_URL, Launch, StatusListener, alive, cmdline, wait_until_gone

# 1 v 1 with the C++ goto behaviour, paced at 2x the wall clock; the world marks a robot
# silent for 1000 ms inactive (long enough that a loaded 2-core machine never trips it).
PACED = ("--team-size", 1, "--behaviour", "goto", "--mode", "realtime", "--speed", 2, "--robot-timeout-ms", 1000,
         "--no-log")
# Runs until stopped: for the faults that end the match.
ENDLESS = ("--team-size", 1, "--behaviour", "goto", "--mode", "realtime", "--duration", 100000, "--no-log")


@pytest.fixture
def status():
    listener = StatusListener()
    yield listener
    listener.stop()


def summary_of(tmp_path):
    return json.loads((tmp_path / "m.json").read_text())


def robot(summary, team, player):
    return next(r for r in summary["robots"] if r["team"] == team and r["player"] == player)


def test_a_shim_killed_during_the_match_leaves_its_robot_inactive_and_the_match_goes_on(tmp_path):
    match = Launch(*PACED, "--duration", 4, "--json", tmp_path / "m.json")
    match.wait_for_line("launch: kick-off,")
    os.kill(match.shim(1, 1), signal.SIGKILL)
    assert match.wait() == 3, match.output()  # played to its end, but a shim died
    summary = summary_of(tmp_path)
    assert summary["frames"] == 120
    assert robot(summary, 0, 1)["frames_answered"] == 120, "the survivor played every frame"
    assert not robot(summary, 1, 1)["active"]
    [death] = summary["shim_deaths"]
    assert (death["team"], death["player"], death["how"]) == (1, 1, "was killed by SIGKILL")
    assert 0 <= death["sim_s"] < 4 and death["restarted_sim_s"] is None
    assert any("team 1 #1's robot_shim was killed by SIGKILL; not restarted (no --restart-dead)" in line
               for line in match.stdout), match.output()


def test_with_restart_dead_a_killed_shim_is_restarted_and_takes_its_robot_back(tmp_path):
    match = Launch(*PACED, "--duration", 10, "--restart-dead", "--json", tmp_path / "m.json")
    match.wait_for_line("launch: kick-off,")
    victim = match.shim(1, 1)
    os.kill(victim, signal.SIGKILL)
    restarted = match.wait_for_line("restarted robot_shim 1/1")
    assert f"(pid {victim})" not in restarted
    assert match.wait() == 3, match.output()
    summary = summary_of(tmp_path)
    returned = robot(summary, 1, 1)
    assert returned["active"], "the restarted shim played the robot to the end"
    assert 0 < returned["frames_answered"] < summary["frames"] == 300
    [death] = summary["shim_deaths"]
    assert death["how"] == "was killed by SIGKILL" and death["taken_back"]
    assert death["sim_s"] <= death["restarted_sim_s"] < 10
    assert any("took the robot back" in line for line in match.stdout), match.output()
    assert any("team 1 player 1 answered again" in line for line in match.stdout), match.output()


def test_a_stopped_shim_is_timed_out_and_rejoins_when_continued(tmp_path, status):
    # Stopped past --live-robot-timeout-ms: a shim that still runs is waited for until then.
    match = Launch(*PACED, "--duration", 8, "--restart-dead", "--live-robot-timeout-ms", 1500,
                   "--json", tmp_path / "m.json")
    match.wait_for_line("launch: kick-off,")
    stopped = match.shim(0, 1)
    os.kill(stopped, signal.SIGSTOP)
    status.wait_for(0, 1, status.type.TIMED_OUT)
    os.kill(stopped, signal.SIGCONT)
    status.wait_for(0, 1, status.type.REJOINED)
    assert match.wait() == 0, match.output()  # stopped is not dead: nothing restarted, nothing lost
    assert any("team 0 player 1 no answer within 1500 ms" in line for line in match.stdout), match.output()
    assert any("team 0 player 1 answered again" in line for line in match.stdout), match.output()
    summary = summary_of(tmp_path)
    assert robot(summary, 0, 1)["active"] and summary["shim_deaths"] == []


def test_a_killed_world_stops_every_shim_and_is_named_and_the_logs_are_kept():
    match = Launch(*ENDLESS)
    match.wait_for_line("launch: kick-off,")
    shims = [match.shim(0, 1), match.shim(1, 1)]
    os.kill(match.child("sim_world"), signal.SIGKILL)
    assert match.wait() == 1, match.output()
    last = match.stderr[-1]
    assert last.startswith("launch: stopping the match: sim_world was killed by SIGKILL (logs in "), last
    logs = last[last.index("(logs in ") + len("(logs in "):-1]
    assert {p.name for p in os.scandir(logs)} >= {"sim_world.log", "robot_shim_0-1.log", "robot_shim_1-1.log"}
    assert not any(alive(p) for p in shims)
    for name in ("robot_shim_0-1.log", "robot_shim_1-1.log"):  # stopped, not left to find out by themselves
        assert "silent for" not in open(os.path.join(logs, name)).read()


@pytest.mark.parametrize("sig, code", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_a_signal_to_the_launcher_stops_every_process_in_one_line(sig, code):
    # As tools/match runs it: the launcher enters a network namespace of its own.
    match = Launch(*ENDLESS, own_netns=True)
    match.wait_for_line("launch: kick-off,")
    processes = match.tree()
    assert sorted("sim_world" in cmdline(p) for p in processes) == [False, False, True], \
        "sim_world and two robot_shims, right under the launcher: " + str([cmdline(p) for p in processes])
    if sig == signal.SIGINT:
        os.killpg(match.pid, sig)  # Ctrl-C on a terminal signals the foreground process group
    else:
        os.kill(match.pid, sig)  # kill PID
    assert match.wait() == code, match.output()
    assert match.stderr == [f"launch: interrupted ({sig.name}), stopping every process"]
    assert wait_until_gone(processes, timeout=0) == [], "left running: " + str([cmdline(p) for p in processes])


def test_a_killed_launcher_leaves_no_process_behind():
    match = Launch(*ENDLESS)
    match.wait_for_line("launch: kick-off,")
    processes = match.tree()
    assert len(processes) == 3
    os.kill(match.pid, signal.SIGKILL)
    assert match.wait() == -signal.SIGKILL
    assert wait_until_gone(processes) == [], "left running: " + str([cmdline(p) for p in processes])


def test_malformed_messages_on_the_watched_channels_are_counted_and_the_score_is_right(tmp_path):
    import lcm
    from touchline import game_state_t, match_event_t

    # A striker against a standing robot, straight into PLAYING: it scores at 0:21 (seed 1;
    # 21.8 s in lockstep, and realtime mode may be a frame or two off).
    match = Launch("--team-size", 1, "--team0", "cpp:Striker", "--team1", "cpp:stand", "--duration", 32,
                   "--mode", "realtime", "--speed", 4, "--no-log", "--json", tmp_path / "m.json",
                   "--set", "rules.initial_s=0", "--set", "rules.ready_s=0", "--set", "rules.set_s=0")
    match.wait_for_line("launch: kick-off,")
    bus = lcm.LCM(LCM_URL)
    game = game_state_t()
    game.score = [-3, 9]  # decodes, but no score is negative
    event = match_event_t()
    event.kind = 99
    bus.publish("TL_GAME", game.encode())
    bus.publish("TL_GAME", game_state_t().encode()[:12])  # truncated
    bus.publish("TL_STATUS", b"\x00" * 40)  # wrong fingerprint
    bus.publish("TL_EVENT", event.encode())
    assert match.wait() == 0, match.output()
    assert any(line.startswith("Match: ") and "score 1:0" in line for line in match.stdout), match.output()
    goals = [line for line in match.stdout if line.startswith("Goals: team 0 at 0:")]
    assert len(goals) == 1 and abs(int(goals[0].split(":")[-1]) - 21.8) < 1, match.output()
    summary = summary_of(tmp_path)
    assert summary["score"] == [1, 0] and summary["goals"] == [{"sim_s": pytest.approx(21.8, abs=1), "team": 0}]
    assert summary["launcher_malformed"] == {"TL_MATCH": 0, "TL_GAME": 2, "TL_STATUS": 1, "TL_EVENT": 1}
    assert any("malformed messages the launcher ignored: TL_GAME 2, TL_STATUS 1, TL_EVENT 1" in line
               for line in match.stdout), match.output()


def test_every_process_gets_a_fresh_match_secret_in_its_environment_only():
    secrets = []
    for _ in range(2):
        match = Launch(*ENDLESS)
        match.wait_for_line("launch: kick-off,")
        processes = match.tree()
        seen = set()
        for pid in processes:
            environ = open(f"/proc/{pid}/environ", "rb").read().split(b"\0")
            values = [v.split(b"=", 1)[1].decode() for v in environ if v.startswith(b"TOUCHLINE_MATCH_SECRET=")]
            assert len(values) == 1, cmdline(pid)
            seen.add(values[0])
        [secret] = seen
        assert len(secret) == 64 and int(secret, 16) >= 0
        assert not any(secret in cmdline(p) for p in processes)
        os.kill(match.pid, signal.SIGTERM)
        assert match.wait() == 143
        secrets.append(secret)
    assert secrets[0] != secrets[1]
