"""The runswift profile in real matches (sim_world + robot_shim over LCM, in a private
network namespace): our rUNSWift-style test behaviour plays a 2 v 2 on the 9 x 6 m field and
scores, broadcasting to its teammates; a shim started without behaviour.py stands, and
plays once the file appears."""
import shutil
from pathlib import Path

from touchline_harness import LCM_URL, ROBOT_SHIM, ROOT, WALK_INI, Proc, start_world

HERE = Path(__file__).resolve().parent
BEHAVIOUR = HERE / "behaviour"
FIELD = ROOT / "config" / "spl2020.ini"
ERROR_LINE = "chest LED magenta"


def runswift_shim(match, team, player, pydir, *params):
    args = [ROBOT_SHIM, "--team", team, "--player", player, "--behaviour", "runswift", "--python-dir", pydir,
            "--field-config", FIELD, "--walk-config", WALK_INI, "--lcm-url", LCM_URL, "--world-timeout", 20]
    for p in params:
        args += ["--param", p]
    proc = Proc(f"robot_shim {team}/{player}", args)
    match.robots[f"{team}/{player}"] = proc
    return proc


def test_our_runswift_behaviour_plays_2v2_and_scores(tmp_path):
    # 300 s: the first goal falls between 200 s and 250 s with seed 1 (at 122 s before the legs
    # held a contact's twist while the walk turned; READY shortened to 5 s; no stuck-game
    # restarts: the ball lies untouched from 68 s to 98 s while our small behaviour looks for it;
    # pushing judged as the thesis does, the rules this timing was measured under).
    match = start_world(tmp_path, 4, 300, "--config", FIELD, "--set", "match.team_size=2",
                        "--set", "rules.ready_s=5", "--set", "rules.game_stuck_s=0",
                        "--set", "rules.pushing_model=thesis", "--seed", 1)
    try:
        for team in (0, 1):
            runswift_shim(match, team, 1, BEHAVIOUR, "skill=Striker", "headskill=HeadScan")
            runswift_shim(match, team, 2, BEHAVIOUR, "skill=Supporter", "headskill=HeadScan")
        summary = match.finish(timeout=300)
    finally:
        match.kill_all()
    assert sum(summary["score"]) >= 1, summary["score"]
    assert summary["comm"]["sent"] > 0 and summary["comm"]["delivered"] > 0, summary["comm"]
    assert summary["comm"]["refused"] == 0, summary["comm"]  # within the league's size and rate
    for robot in summary["robots"]:
        assert robot["frames_missed"] == 0, robot
        assert robot["behaviour_cpu_us_mean"] > 0, robot
    for name, shim in match.robots.items():
        assert not any(ERROR_LINE in line for line in shim.stderr), f"{name}:\n" + "\n".join(shim.stderr)


def test_a_shim_without_behaviour_py_stands_until_the_file_appears(tmp_path):
    pydir = tmp_path / "behaviours"
    pydir.mkdir()
    match = start_world(tmp_path, 1, 600, "--mode", "realtime", "--speed", "5", "--config", FIELD,
                        "--set", "match.team_size=1")
    try:
        shim = runswift_shim(match, 0, 1, pydir, "skill=Striker", "headskill=HeadScan")
        shim.wait_for_line(f"robot_shim 0/1: no behaviour.py (nor package behaviour/) in {pydir}")
        shutil.copytree(BEHAVIOUR, pydir, dirs_exist_ok=True)
        shim.wait_for_line("robot_shim 0/1: reloaded behaviour", timeout=10)
        assert shim.popen.poll() is None, "the shim must keep running"
        assert sum(ERROR_LINE in line for line in shim.stderr) == 1, "\n".join(shim.stderr)
    finally:
        match.kill_all()


def test_the_same_seed_plays_the_same_match(tmp_path):
    hashes = []
    for run in range(2):
        match = start_world(tmp_path, 4, 90, "--config", FIELD, "--set", "match.team_size=2",
                            "--set", "rules.ready_s=5", "--seed", 7)
        try:
            for team in (0, 1):
                runswift_shim(match, team, 1, BEHAVIOUR, "skill=Striker", "headskill=HeadScan")
                runswift_shim(match, team, 2, BEHAVIOUR, "skill=Supporter", "headskill=HeadScan")
            hashes.append(match.finish(timeout=300)["truth_hash"])
        finally:
            match.kill_all()
    assert hashes[0] == hashes[1], hashes
