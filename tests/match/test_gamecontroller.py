"""sim_world taking the game from the official GameController's UDP packets (on loopback)."""
import socket
import struct

import lcm

from touchline_harness import robot_entry, start_robot, start_world

GC_PORT = 3838  # each test file runs in a private network namespace: no clash


def gc_packet(state: int, score: tuple, penalised_team1: tuple = ()) -> bytes:
    """A GameController data packet, version 15 (RoboCupGameControlData.h, 118 bytes)."""
    header = struct.pack("<4sBBBBBBBBBBhh", b"RGme", 15, 7, 4, 0, 0, 0, state, 0, 1, 11, 300, 0)
    teams = b""
    for index, (number, goals) in enumerate(zip((11, 22), score)):
        players = b"".join(struct.pack("<BB", 5 if (index == 1 and p in penalised_team1) else 0, 20 if index == 1 and p in penalised_team1 else 0)
                           for p in range(1, 21))
        teams += struct.pack("<BBBBBBHH", number, 0, 1, 1, goals, 0, 0, 1200) + players
    packet = header + teams
    assert len(packet) == 118
    return packet


def test_the_gamecontroller_decides_the_game(tmp_path):
    log = tmp_path / "gc.lcmlog"
    # Paced to the wall clock: in lockstep the match could end before the packet arrives.
    match = start_world(tmp_path, 2, 4.0, "--gamecontroller", f"127.0.0.1:{GC_PORT}", "--log", log,
                        "--mode", "realtime")
    start_robot(match, 0, 1, "walk", forward=200)
    start_robot(match, 1, 1, "walk", forward=200)
    match.world.wait_for_line("taking the game from GameController packets")
    match.world.wait_for_line("kick-off")
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as gc:
        gc.sendto(b"garbage", ("127.0.0.1", GC_PORT))
        gc.sendto(gc_packet(state=3, score=(2, 1), penalised_team1=(1,)), ("127.0.0.1", GC_PORT))
    match.world.wait_for_line("GameController says PLAYING")
    summary = match.finish()

    from touchline import game_state_t
    states = [game_state_t.decode(e.data) for e in lcm.EventLog(str(log), "r") if e.channel == "TL_GAME"]
    assert states[0].state == game_state_t.INITIAL  # nothing from the GameController yet
    playing = [s for s in states if s.state == game_state_t.PLAYING]
    assert playing and list(playing[-1].score) == [2, 1] and playing[-1].secs_remaining == 300
    # The GameController penalised team 1 player 1, and only it.
    assert robot_entry(summary, 1, 1)["penalised"]
    assert not robot_entry(summary, 0, 1)["penalised"]


def test_a_bad_gamecontroller_address_is_one_line_and_exit_2(tmp_path):
    match = start_world(tmp_path, 1, 1.0, "--gamecontroller", "127.0.0.1:notaport")
    assert match.world.wait() == 2
    assert "--gamecontroller must be [ADDRESS:]PORT" in match.world.stderr[-1]
