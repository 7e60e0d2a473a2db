"""The in-process match (touchline_match, tools/launch.py --in-process): the world and every
robot in one process play the same match as sim_world and robot_shim processes in lockstep:
same seed, same truth hash and the same referee's events, for C++, Python and mixed teams.
Bad options are one line and exit code 2. Runs in a private network namespace (tools/netns)
for the lockstep runs it compares with."""
import json
import re
import os
import shutil
import subprocess
import sys

import pytest

from touchline_harness import BUILD, ROOT

TOUCHLINE_MATCH = BUILD / "bin" / "touchline_match"
LAUNCH = [sys.executable, str(ROOT / "tools" / "launch.py"), "--build-dir", str(BUILD), "--no-log", "--no-progress"]
MATCH_S = 600  # a wall-clock bound that only turns a hang into a failure
HANG_S = 10
ROBOT = ["--team", "0", "--player", "1"]


def launch(tmp_path, name, *args, env=None):
    out = tmp_path / f"{name}.json"
    result = subprocess.run([*LAUNCH, *map(str, args), "--json", out], capture_output=True, text=True,
                            timeout=MATCH_S, env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    return json.loads(out.read_text()), result.stdout


@pytest.mark.parametrize("team0, team1, duration_s", [
    ("cpp:Team", "cpp:Team", 90),  # long enough for penalties, falls and set plays
    ("py:Team", "py:Team", 10),
    ("cpp:Team", "py:Team", 10),
])
def test_same_seed_same_match_as_lockstep(tmp_path, team0, team1, duration_s):
    match = ["--team0", team0, "--team1", team1, "--duration", duration_s, "--seed", 2,
             "--config", ROOT / "config" / "spl2020.ini"]
    if duration_s == 90:  # the thesis' pushing model calls pushes soonest, and every push fells: a fall within 90 s
        match += ["--set", "rules.pushing_model=thesis", "--set", "rules.fall_probability=1"]
    lockstep, _ = launch(tmp_path, "lockstep", *match)
    in_process, report = launch(tmp_path, "in_process", *match, "--in-process")
    assert in_process["truth_hash"] == lockstep["truth_hash"]
    for key in ("frames", "score", "ball", "goals", "penalties", "falls", "set_plays", "comm"):
        assert in_process[key] == lockstep[key], key
    assert [(r["team"], r["player"], r["frames_answered"]) for r in in_process["robots"]] == \
        [(r["team"], r["player"], r["frames_answered"]) for r in lockstep["robots"]]
    if duration_s == 90:  # the events compared above are not all empty
        assert in_process["penalties"] and in_process["falls"] and in_process["set_plays"]
    assert in_process["mode"] == "in-process" and lockstep["mode"] == "lockstep"
    assert in_process["wall_s"] > 0 and in_process["rtf"] > 0
    assert f"in-process mode, seed 2, score {in_process['score'][0]}:{in_process['score'][1]}, " \
           f"truth hash {in_process['truth_hash']}" in report


def test_another_seed_is_another_match(tmp_path):
    match = ["--team0", "cpp:Team", "--team1", "cpp:Team", "--duration", 5, "--in-process"]
    a, _ = launch(tmp_path, "a", *match, "--seed", 1)
    b, _ = launch(tmp_path, "b", *match, "--seed", 2)
    assert a["truth_hash"] != b["truth_hash"]


def test_in_process_needs_no_network(tmp_path):
    # No namespace of the launcher's own and no route at all: nothing of the match goes over LCM.
    if not shutil.which("unshare") or subprocess.run(["unshare", "--net", "true"]).returncode != 0:
        pytest.skip("cannot make a network namespace here")
    env = {k: v for k, v in os.environ.items() if k != "TOUCHLINE_IN_NETNS"}
    out = tmp_path / "summary.json"
    result = subprocess.run(["unshare", "--net", *LAUNCH, "--in-process", "--duration", "2", "--team0", "cpp:Team",
                             "--team1", "py:Team", "--json", out], capture_output=True, text=True, timeout=MATCH_S,
                            env=env)
    assert result.returncode == 0, result.stdout + result.stderr
    assert json.loads(out.read_text())["frames"] == 60


def run(*args):
    return subprocess.run([str(a) for a in [TOUCHLINE_MATCH, *args]], capture_output=True, text=True, timeout=HANG_S)


@pytest.mark.parametrize("args, message", [
    (["--", "--team", "0", "--player", "8"], "robot 1: --player must be an integer in [1, 7] (got '8')"),
    (["--log-level", "loud", "--", *ROBOT], "--log-level loud: not a level ("),
    (["--", *ROBOT, "--", "--team", "1", "--player", "1", "--behaviour", "nope"], "unknown behaviour 'nope'"),
    (["--", *ROBOT, "--behaviour", "goto", "--param", "x=abc"], "parameter x must be a number"),
    (["--", *ROBOT, "--frobnicate"], "robot 1: unrecognised option '--frobnicate'"),
    (["--", *ROBOT, "--walk-engine", "moonwalk"], "robot 1: --walk-engine: unknown walk engine 'moonwalk'"),
    (["--", *ROBOT, "--walk-config", "/nonexistent.ini"], "cannot open config file (No such file or directory)"),
    (["--", *ROBOT, "--behaviour", "py:"], "robot 1: --behaviour"),
    (["--", *ROBOT, "--", *ROBOT], "robot 2 (team 0 player 1)"),  # the roster refuses a second 0/1
    (["--set", "match.team_size=2", "--", "--team", "0", "--player", "3"], "robot 1 (team 0 player 3)"),
    (["--", *ROBOT, "--", "--team", "1", "--player", "1", "--data-dir", "/tmp"], "robot 2: --data-dir /tmp differs"),
    (["--", *ROBOT, "--behaviour", "py:no_such_module"], "no_such_module"),
    (["--seed", "-1", "--", *ROBOT], "--seed must be an integer in [0, 18446744073709551615] (got '-1')"),
    (["--summary", "/nonexistent/s.json", "--", *ROBOT], "--summary /nonexistent/s.json: cannot write there"),
    (["--config", "/nonexistent.ini", "--", *ROBOT], "/nonexistent.ini: cannot open config file"),
    ([], "no robots"),
])
def test_bad_options_are_one_line(args, message):
    result = run(*args)
    assert result.returncode == 2, (result.returncode, result.stderr)
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr


def test_the_log_level_chooses_the_lines():
    """Progress lines (every 10 simulated seconds) are information: --log-level warning keeps
    only what went wrong, and the match is the same."""
    said = {level: run("--duration", 20, "--log-level", level, "--", *ROBOT, "--behaviour", "stand")
            for level in ("info", "warning")}
    assert all(r.returncode == 0 for r in said.values()), {k: r.stderr for k, r in said.items()}
    progress = [re.fullmatch(r"touchline_match: (\d+) s simulated, x[\d.]+ real time", line)
                for line in said["info"].stderr.splitlines()]
    assert all(progress) and [int(m.group(1)) for m in progress] == [10, 20], said["info"].stderr
    assert said["warning"].stderr == ""
    hashes = {level: re.search(r"truth hash (\w+)", r.stdout).group(1) for level, r in said.items()}
    assert hashes["info"] == hashes["warning"]


def test_print_match_is_the_config_after_every_set():
    result = run("--config", ROOT / "config" / "spl2020.ini", "--set", "match.team_size=7", "--duration", "12")
    assert result.returncode == 2  # no robots: a usage error, not a match
    result = run("--config", ROOT / "config" / "spl2020.ini", "--set", "match.team_size=7", "--duration", "12",
                 "--print-match")
    assert result.returncode == 0, result.stderr
    plan = json.loads(result.stdout)
    assert {key: plan[key] for key in ("team_size", "field_length_mm", "field_width_mm", "duration_s")} == {
        "team_size": 7, "field_length_mm": 9000, "field_width_mm": 6000, "duration_s": 12}
    assert plan["planned_s"] == 12  # two halves last longer than 12 s: the cap is the plan


def test_help_documents_the_world_and_the_robots():
    result = run("--help")
    assert result.returncode == 0, result.stderr
    for option in ["--config", "--set", "--duration", "--seed", "--summary", "--print-match", "--quiet"]:
        assert option in result.stdout
    assert "-- [robot options]" in result.stdout and "goto" in result.stdout and "py:MODULE" in result.stdout


def test_the_in_process_log_holds_what_the_world_says(tmp_path):
    """touchline_match --log: the world's messages and each robot's answer, readable as a
    lockstep match's log: the set-up first, a truth per frame, the game, the events, the acts."""
    sys.path.insert(0, str(BUILD / "lcm_types" / "gen" / "python"))
    sys.path.insert(0, str(ROOT / "tools"))
    import lcm
    import match_stats
    from touchline import act_t, game_state_t, match_event_t, world_truth_t

    log = tmp_path / "match.lcmlog"
    summary = tmp_path / "summary.json"
    result = subprocess.run([str(a) for a in [TOUCHLINE_MATCH, "--config", ROOT / "config" / "spl2020.ini", "--duration", 90,
                             "--seed", 7, "--quiet", "--summary", summary, "--log", log,
                             "--", "--team", "0", "--player", "2", "--behaviour", "Team",  # field players, not goalies
                             "--field-config", ROOT / "config" / "spl2020.ini",
                             "--", "--team", "1", "--player", "2", "--behaviour", "Team",
                             "--field-config", ROOT / "config" / "spl2020.ini"]],
                            capture_output=True, text=True, timeout=MATCH_S)
    assert result.returncode == 0, result.stderr
    events = list(lcm.EventLog(str(log), "r"))
    assert events[0].channel == "TL_MATCH"
    truths = [world_truth_t.decode(e.data) for e in events if e.channel == "TL_TRUTH"]
    played = json.loads(summary.read_text())
    assert [t.frame for t in truths] == list(range(played["frames"]))  # the frame each truth ends
    assert all(e.timestamp == t.utime for e, t in zip([e for e in events if e.channel == "TL_TRUTH"], truths))
    states = [game_state_t.decode(e.data).state for e in events if e.channel == "TL_GAME"]
    assert game_state_t.PLAYING in states and states[-1] == game_state_t.FINISHED
    kinds = [match_event_t.decode(e.data).kind for e in events if e.channel == "TL_EVENT"]
    assert len(kinds) == len(played["match_events"]) and match_event_t.STATE_CHANGE in kinds
    # The statistics a sweep takes from a lockstep log come from this one too.
    stats = match_stats.analyse_log(log)
    assert sum(stats["possession_frames"]) > 0
    assert 0 < stats["playing_share"] < 1  # the set-up states before kick-off are not play
    assert stats["ball_moving_share"] <= stats["playing_share"]
    # Each robot's act of each frame, on its own channel, before the truth that frame ends in.
    for channel, team in (("TL_ACT_0_2", 0), ("TL_ACT_1_2", 1)):
        acts = [(i, act_t.decode(e.data)) for i, e in enumerate(events) if e.channel == channel]
        assert [a.frame for _, a in acts] == list(range(played["frames"]))
        assert all(a.team == team and a.player == 2 for _, a in acts)
        first_truth = next(i for i, e in enumerate(events) if e.channel == "TL_TRUTH")
        assert acts[0][0] < first_truth
        assert any(a.team_message for _, a in acts)  # the Team's messages: the viewer's roles
