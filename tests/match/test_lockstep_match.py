"""Multi-process matches: sim_world and robot_shim processes in lockstep over LCM."""
import math

import pytest

from touchline_harness import (LCM_URL, ROBOTS_URL, UPLINK_URL, sealed, nominal_distance, robot_entry, start_robot, start_world,
                               walk_def)
from truth_listener import TruthListener, logged_truths, total_turn

WALK_S = 10.0
NO_REFEREE = ("--set", "rules.referee=false")  # calibration: no INITIAL/SET holding robots still


def walked(summary_start: dict, summary_end: dict) -> tuple:
    return summary_end["x_mm"] - summary_start["x_mm"], summary_end["y_mm"] - summary_start["y_mm"]


@pytest.fixture
def truth():
    listener = TruthListener(LCM_URL)
    yield listener
    listener.stop()


def start_pose(frames, team, player):
    r = next(r for r in frames[0].robots if r.team == team and r.player == player)
    return r.body


def test_full_speed_forward_covers_the_nominal_distance(tmp_path):
    walk = walk_def()
    match = start_world(tmp_path, 1, WALK_S, *NO_REFEREE, "--log", tmp_path / "match.lcmlog")
    start_robot(match, 0, 1, "walk", forward=walk["max_forward_mm_s"])
    summary = match.finish()
    start = start_pose(logged_truths(tmp_path / "match.lcmlog"), 0, 1)
    end = robot_entry(summary, 0, 1)
    # Team 0 starts on the touchline facing +y: forward is +y.
    distance = end["y_mm"] - start.y_mm
    nominal = nominal_distance(walk["max_forward_mm_s"], walk["accel_forward_mm_s2"], WALK_S)
    assert distance == pytest.approx(nominal, rel=0.10)
    assert abs(end["x_mm"] - start.x_mm) < 0.05 * nominal, "walked straight"
    assert end["frames_answered"] == summary["frames"] == 300


def test_full_speed_sideways_both_ways_covers_the_nominal_distance(tmp_path):
    walk = walk_def()
    speed = walk["max_left_mm_s"]
    match = start_world(tmp_path, 2, WALK_S, "--set", "match.team_size=4", *NO_REFEREE,
                        "--log", tmp_path / "match.lcmlog")
    # Both end up walking towards +x, on opposite touchlines: team 0 faces +y, so its
    # right is +x; team 1 faces -y, so its left is +x.
    start_robot(match, 0, 4, "walk", left=-speed)
    start_robot(match, 1, 4, "walk", left=speed)
    summary = match.finish()
    nominal = nominal_distance(speed, walk["accel_left_mm_s2"], WALK_S)
    frames = logged_truths(tmp_path / "match.lcmlog")
    for team in (0, 1):
        start = start_pose(frames, team, 4)
        end = robot_entry(summary, team, 4)
        assert end["x_mm"] - start.x_mm == pytest.approx(nominal, rel=0.10), f"team {team}"
        assert abs(end["y_mm"] - start.y_mm) < 0.05 * nominal


def test_full_speed_turn_covers_the_nominal_angle(tmp_path):
    walk = walk_def()
    rate = walk["max_turn_rad_s"]
    match = start_world(tmp_path, 1, WALK_S, *NO_REFEREE, "--log", tmp_path / "match.lcmlog")
    start_robot(match, 0, 1, "walk", turn=rate)
    summary = match.finish()
    frames = logged_truths(tmp_path / "match.lcmlog")
    assert len(frames) == summary["frames"]
    nominal = nominal_distance(rate, walk["accel_turn_rad_s2"], WALK_S)
    assert total_turn(frames, 0, 1) == pytest.approx(nominal, rel=0.10)
    start = start_pose(frames, 0, 1)
    end = robot_entry(summary, 0, 1)
    assert math.hypot(end["x_mm"] - start.x_mm, end["y_mm"] - start.y_mm) < 150, "turned on the spot"


def test_eight_robots_all_answer_every_frame(tmp_path):
    match = start_world(tmp_path, 8, 5.0)
    for team in (0, 1):
        for player in range(1, 5):
            start_robot(match, team, player, "walk", forward=150, turn=0.2 * player)
    summary = match.finish()
    assert summary["frames"] == 150
    assert len(summary["robots"]) == 8
    for r in summary["robots"]:
        assert r["active"] and r["frames_answered"] == 150 and r["frames_missed"] == 0, r
    assert summary["malformed"] == 0 and summary["stale"] == 0


def test_a_killed_shim_is_reported_and_the_match_goes_on_and_it_may_rejoin(tmp_path, truth):
    # Paced at 2x the wall clock: in lockstep the match could end before the kill lands.
    match = start_world(tmp_path, 2, 8.0, "--robot-timeout-ms", "300", "--mode", "realtime", "--speed", "2")
    start_robot(match, 0, 1, "walk", forward=100)
    victim = start_robot(match, 0, 2, "walk", forward=100)
    truth.wait_for_frame(30)
    victim.kill()
    match.world.wait_for_line("team 0 player 2 no answer within 300 ms")
    truth.wait_for_frame(truth.frames[-1].frame + 30)  # the world went on without it
    inactive = [r for r in truth.frames[-1].robots if r.player == 2][0]
    assert not inactive.active
    del match.robots[next(k for k, p in match.robots.items() if p is victim)]
    start_robot(match, 0, 2, "walk", forward=100)  # a restarted shim takes the robot back
    match.world.wait_for_line("team 0 player 2 answered again")
    summary = match.finish()
    survivor = robot_entry(summary, 0, 1)
    assert survivor["frames_answered"] == summary["frames"] == 240
    returned = robot_entry(summary, 0, 2)
    assert returned["active"] and returned["frames_missed"] >= 1
    # Every frame counts once: answered, or stepped without its answer while it was dead.
    assert returned["frames_answered"] + returned["frames_missed"] == summary["frames"]


def test_a_robot_stopped_past_its_timeout_is_waited_for_while_its_shim_runs(tmp_path):
    # A busy machine or a debugger's breakpoint holds a shim longer than --robot-timeout-ms.
    # Timing it out would make it stand still, and the match would not be its seed's.
    import signal
    import time
    hashes = []
    for stop_s in (0.0, 0.6):
        # Realtime at 1x: the stop lands mid-match (in lockstep the match could end first).
        match = start_world(tmp_path, 2, 3.0, "--robot-timeout-ms", "100", "--mode", "realtime", "--speed", "1")
        robots = [start_robot(match, 0, 1, "walk", forward=100), start_robot(match, 1, 1, "walk", forward=100)]
        if stop_s:
            match.world.wait_for_line("kick-off")
            robots[0].popen.send_signal(signal.SIGSTOP)
            time.sleep(stop_s)  # the stop itself, not a wait for anything
            robots[0].popen.send_signal(signal.SIGCONT)
        summary = match.finish()
        if stop_s:
            assert summary["slow_answers"] >= 1, summary  # the stop was longer than the timeout
        for team in (0, 1):
            entry = robot_entry(summary, team, 1)
            assert entry["active"] and entry["frames_missed"] == 0, entry
        hashes.append(summary["truth_hash"])
    assert hashes[0] == hashes[1]


def test_when_every_robot_stops_at_once_the_world_waits_and_they_come_back(tmp_path):
    import signal
    match = start_world(tmp_path, 2, 4.0, "--robot-timeout-ms", "200", "--live-robot-timeout-ms", "300")
    robots = [start_robot(match, 0, 1, "walk", forward=100), start_robot(match, 1, 1, "walk", forward=100)]
    match.world.wait_for_line("kick-off")
    for robot in robots:
        robot.popen.send_signal(signal.SIGSTOP)
    match.world.wait_for_line("team 0 player 1 no answer within 300 ms")
    match.world.wait_for_line("team 1 player 1 no answer within 300 ms")
    for robot in robots:
        robot.popen.send_signal(signal.SIGCONT)
    match.world.wait_for_line("team 0 player 1 answered again")
    match.world.wait_for_line("team 1 player 1 answered again")
    summary = match.finish()
    for team in (0, 1):
        entry = robot_entry(summary, team, 1)
        assert entry["active"], entry
        assert entry["frames_answered"] + entry["frames_missed"] == summary["frames"] == 120
        assert entry["frames_missed"] < 30, entry  # the world waited for them instead of racing on


def test_a_sense_from_far_in_the_future_does_not_silence_a_shim(tmp_path):
    import lcm
    from touchline import robot_sense_t, sense_t

    match = start_world(tmp_path, 1, 3.0, "--mode", "realtime")
    shim = start_robot(match, 0, 1, "walk", forward=100)
    match.world.wait_for_line("kick-off")
    forged = sense_t()  # tagged with the match's own secret: only the frame is wrong
    forged.frame, forged.utime, forged.motion_ticks = 2 ** 62, 0, 3
    mine = robot_sense_t()
    mine.team, mine.player, mine.active = 0, 1, True
    forged.robots, forged.num_robots = [mine], 1
    lcm.LCM(ROBOTS_URL).publish("TL_SENSE", sealed("TL_SENSE", forged.encode()))  # where robots hear it
    shim.wait_for_line("is not a frame of a match")
    summary = match.finish()
    assert robot_entry(summary, 0, 1)["frames_answered"] == summary["frames"] == 90


def test_when_the_world_is_killed_each_shim_says_so_and_exits(tmp_path):
    match = start_world(tmp_path, 1, 30.0, "--mode", "realtime")
    shim = start_robot(match, 0, 1, "walk", world_timeout_s=1, forward=100)
    match.world.wait_for_line("kick-off")
    match.world.kill()
    assert shim.wait(timeout=10) == 1
    assert any("sim_world silent for 1 s, giving up" in line for line in shim.stderr), shim.stderr


@pytest.fixture
def lossy_loopback():
    """Drops one in ten of the match's UDP packets in this test's network namespace (nftables)."""
    import subprocess
    rules = ["add table inet touchline_loss",
             'add chain inet touchline_loss input { type filter hook input priority 0 ; }',
             "add rule inet touchline_loss input udp dport 7667-7669 numgen random mod 10 == 0 drop"]  # the 3 ports
    for rule in rules:
        subprocess.run(["nft", *rule.split()], check=True)
    yield
    subprocess.run(["nft", "delete", "table", "inet", "touchline_loss"], check=True)


def test_a_lost_sense_or_answer_is_sent_again_and_no_frame_is_missed(tmp_path, lossy_loopback):
    # The resends alone must save every frame: the robot timeout (wall time, 1 s by default) is
    # raised so that a process stalled on a loaded machine (CI once saw 76 of 90 frames) is not
    # taken for a lost packet. Timeouts have their own tests.
    match = start_world(tmp_path, 2, 3.0, "--robot-timeout-ms", "10000")
    start_robot(match, 0, 1, "walk", forward=100)
    start_robot(match, 1, 1, "walk", forward=100)
    summary = match.finish()
    for team in (0, 1):
        entry = robot_entry(summary, team, 1)
        assert entry["frames_answered"] == summary["frames"] == 90, entry
        assert entry["frames_missed"] == 0, entry
    assert summary["resent_senses"] > 0  # packets were lost and the world noticed


def test_second_shim_claiming_a_robot_is_refused(tmp_path):
    # Paced to the wall clock: a lockstep match of 3 s could end before the intruder's join.
    match = start_world(tmp_path, 1, 3.0, "--mode", "realtime")
    start_robot(match, 1, 3)
    match.world.wait_for_line("kick-off")
    intruder = start_robot(match, 1, 3)
    assert intruder.wait() == 2
    assert any("team 1 player 3 is already played by another robot_shim" in l for l in intruder.stderr), intruder.stderr
    del match.robots[next(k for k, p in match.robots.items() if p is intruder)]
    match.finish()


def test_player_outside_the_team_is_refused(tmp_path):
    match = start_world(tmp_path, 1, 2.0, "--set", "match.team_size=3")
    outsider = start_robot(match, 0, 5)
    assert outsider.wait() == 2
    assert outsider.stderr[-1].endswith("player 5 is not in a team of 3 (players 1..3)"), outsider.stderr
    del match.robots[next(iter(match.robots))]
    start_robot(match, 0, 3)
    match.finish()


def test_same_seed_gives_the_same_truth_stream(tmp_path):
    hashes = []
    for _ in range(2):
        match = start_world(tmp_path, 4, 6.0, "--seed", "7")
        for player, (x, y) in enumerate([(-2000, 0), (-1000, 1000), (-1000, -1000), (0, 0)], start=1):
            start_robot(match, 0, player, "goto", x=x, y=y, theta=0.5)
        summary = match.finish()
        hashes.append(summary["truth_hash"])
    assert hashes[0] == hashes[1]


def test_malformed_messages_are_reported_and_ignored(tmp_path):
    import lcm
    from touchline import act_t

    # Paced to the wall clock: a lockstep match of 3 s could end before the garbage arrives.
    match = start_world(tmp_path, 1, 3.0, "--mode", "realtime")
    start_robot(match, 0, 1, "walk", forward=100)
    match.world.wait_for_line("kick-off")
    bus = lcm.LCM(UPLINK_URL)  # where the world hears answers
    # Authenticated (made with the match's secret) but malformed: decoded, refused, counted.
    bus.publish("TL_ACT_0_1", sealed("TL_ACT_0_1", b"\x00garbage"))
    bad = act_t()
    bad.team, bad.player, bad.motion_ticks = 0, 9, 0
    bad.team_message = b""  # lcm-gen 1.3.1's Python default for byte arrays is a str
    bus.publish("TL_ACT_0_9", sealed("TL_ACT_0_9", bad.encode()))
    match.world.wait_for_line("cannot decode as act_t")
    match.world.wait_for_line("no such robot (team 0, player 9)")
    summary = match.finish()
    assert summary["malformed"] == 2
    assert robot_entry(summary, 0, 1)["frames_answered"] == summary["frames"]


def test_messages_not_made_with_the_match_secret_are_dropped_unread(tmp_path):
    import lcm
    from touchline import act_t, game_state_t

    match = start_world(tmp_path, 1, 3.0, "--mode", "realtime")
    shim = start_robot(match, 0, 1, "walk", forward=100)
    match.world.wait_for_line("kick-off")
    bus, robots_hear = lcm.LCM(UPLINK_URL), lcm.LCM(ROBOTS_URL)
    # A forger who has seen the traffic but not the secret: a valid act with no tag, one
    # with a tag made with another secret, a FINISHED for every robot, and a tag lifted
    # from another channel.
    forged = act_t()
    forged.team, forged.player, forged.motion_ticks = 0, 1, 0
    forged.team_message = b""
    bus.publish("TL_ACT_0_1", forged.encode())
    bus.publish("TL_ACT_0_1", sealed("TL_ACT_0_1", forged.encode(), secret_hex="ab" * 32))
    finished = game_state_t()
    finished.state = game_state_t.FINISHED
    robots_hear.publish("TL_GAME", sealed("TL_GAME", finished.encode(), secret_hex="cd" * 32))
    bus.publish("TL_ACT_0_1", sealed("TL_ACT_0_2", forged.encode()))
    match.world.wait_for_line("without a valid tag")
    summary = match.finish()
    assert summary["unauthenticated"] == 3
    assert summary["malformed"] == 0
    assert robot_entry(summary, 0, 1)["frames_answered"] == summary["frames"]
    assert shim.wait() == 0  # played to the end: the forged FINISHED did not stop it


def test_realtime_mode_paces_and_free_mode_never_waits(tmp_path):
    paced = start_world(tmp_path, 1, 2.0, "--mode", "realtime", "--speed", "10")
    start_robot(paced, 0, 1, "walk", forward=100)
    summary = paced.finish()
    assert summary["wall_s"] >= 2.0 / 10  # never ahead of the clock
    assert robot_entry(summary, 0, 1)["frames_answered"] == 60

    free = start_world(tmp_path, 1, 2.0, "--mode", "free", "--speed", "10")
    start_robot(free, 0, 1, "walk", forward=100)
    summary = free.finish()
    assert summary["wall_s"] >= 2.0 / 10
    assert robot_entry(summary, 0, 1)["frames_answered"] > 0


def test_each_port_of_the_url_carries_its_own_channels(tmp_path):
    """The one --lcm-url gives three ports (bridge/lcm lanes.hpp): the world publishes on the URL's
    port; answers, joins and Blackboards go to the port above, which only the world joins; the
    sense, the game and the join replies are copied to the port above that, the only one robots
    join. So no robot is woken by another's answer or by the truth. A listener on each port
    hears its own channels."""
    import collections
    import select
    import time

    import lcm

    heard = {url: collections.Counter() for url in (LCM_URL, UPLINK_URL, ROBOTS_URL)}
    buses = {url: lcm.LCM(url) for url in heard}
    for url, bus in buses.items():
        bus.subscribe("TL_.*", lambda channel, data, url=url: heard[url].update([channel]))  # not LCM_SELF_TEST
    match = start_world(tmp_path, 2, 3.0, "--mode", "realtime")
    for player in (1, 2):
        start_robot(match, 0, player, "walk", forward=100)
    fds = {bus.fileno(): bus for bus in buses.values()}
    deadline = time.monotonic() + 60
    while match.world.popen.poll() is None and time.monotonic() < deadline:
        for fd in select.select(list(fds), [], [], 0.05)[0]:
            fds[fd].handle()
    summary = match.finish()
    world_port, answers_port, robots_port = heard[LCM_URL], heard[UPLINK_URL], heard[ROBOTS_URL]
    frames = summary["frames"]
    assert world_port["TL_SENSE"] >= frames and world_port["TL_TRUTH"] == frames
    assert {"TL_MATCH", "TL_GAME", "TL_STATUS", "TL_JOIN_REPLY"} <= world_port.keys(), world_port
    assert answers_port["TL_ACT_0_1"] >= frames and answers_port["TL_ACT_0_2"] >= frames
    assert set(answers_port) == {"TL_JOIN", "TL_ACT_0_1", "TL_ACT_0_2", "TL_BLACKBOARD_0_1", "TL_BLACKBOARD_0_2"}
    assert set(robots_port) == {"TL_SENSE", "TL_GAME", "TL_JOIN_REPLY"}, robots_port
    for channel in robots_port:
        assert robots_port[channel] == world_port[channel], channel  # a copy of each, no more
    assert not set(world_port) & set(answers_port), world_port
