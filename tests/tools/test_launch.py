"""The launcher: plays a match, records every message, and stops cleanly on failure (faults and signals:
test_launch_faults.py)."""
import json
import subprocess
import sys
from pathlib import Path

import lcm
from conftest import LAUNCH, ROOT
from touchline import act_t


def launch(*args, **kwargs):
    return subprocess.run([*LAUNCH, *map(str, args)], capture_output=True, text=True, timeout=120, **kwargs)


def test_match_is_summarised_and_every_truth_frame_is_in_the_log(tmp_path):
    result = launch("--team-size", 2, "--duration", 4, "--log-dir", tmp_path, "--json", tmp_path / "m.json")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "m.json").read_text())
    assert summary["frames"] == 120 and len(summary["robots"]) == 4
    assert all(r["frames_answered"] == 120 for r in summary["robots"])
    assert "team 1 #2" in result.stdout and "truth hash" in result.stdout
    assert "Goals: " in result.stdout and "Penalties: " in result.stdout
    assert {"goals", "penalties", "falls", "set_plays"} <= summary.keys()
    assert all(r["localisation_rms_mm"] >= 0 for r in summary["robots"])
    logs = list(tmp_path.glob("*_seed1.lcmlog"))
    assert len(logs) == 1
    truth_frames = [e for e in lcm.EventLog(str(logs[0]), "r") if e.channel == "TL_TRUTH"]
    assert len(truth_frames) == summary["frames"], "the log lost truth frames"
    # Every answer the world took is in the log (a shim's repeat of an answer, to a re-sent
    # sense, is recorded too: count each robot's frame once).
    answers = {(e.channel, act_t.decode(e.data).frame) for e in lcm.EventLog(str(logs[0]), "r")
               if e.channel.startswith("TL_ACT_")}
    assert len(answers) == 4 * summary["frames"], "the log lost answers"


def test_a_failing_robot_stops_the_match_and_is_named(tmp_path):
    bad_walk = tmp_path / "walk.ini"
    bad_walk.write_text("[walk]\nperiod_s = -1\n")
    result = launch("--team-size", 1, "--duration", 5, "--walk-config", bad_walk, "--no-log")
    assert result.returncode == 1
    line = result.stderr.strip().splitlines()[-1]
    assert "robot_shim" in line and "exited with code 2" in line and "period_s" in line, result.stderr


def test_bad_options_are_one_line(tmp_path):
    result = launch("--team-size", 9)
    assert result.returncode == 2
    assert "--team-size must be 1..7" in result.stderr
    result = launch("--restart-dead", "--mode", "free")
    assert result.returncode == 2
    assert result.stderr.strip().splitlines()[-1].endswith(
        "--restart-dead needs lockstep or realtime mode: in free mode the world never marks a silent robot "
        "inactive, so a restarted shim could not take it over")
    result = launch("--robot-timeout-ms", 0)
    assert result.returncode == 2 and "--robot-timeout-ms must be > 0" in result.stderr


def test_team_specs_carry_skill_parameters():
    sys.path.insert(0, str(ROOT / "tools"))
    from launch import team_behaviour

    assert team_behaviour("py:Team") == ["--behaviour", "py", "--param", "skill=Team"]
    assert team_behaviour("cpp:Team,walker=learned,policy=p/x.policy") == [
        "--behaviour", "Team", "--param", "walker=learned", "--param", "policy=p/x.policy"]
    assert team_behaviour("py:Striker,walker=learned") == [
        "--behaviour", "py", "--param", "skill=Striker", "--param", "walker=learned"]
    assert team_behaviour("runswift:WalkToPoint,headskill=HeadFindBall", Path("/rs/behaviours")) == [
        "--behaviour", "runswift", "--python-dir", "/rs/behaviours", "--param", "skill=WalkToPoint",
        "--param", "headskill=HeadFindBall"]
    for bad in ("Team", "java:Team", "py:", "py:Team,walker", "py:Team,=x", "py:a:b", "runswift:"):
        assert team_behaviour(bad) is None, bad
    result = launch("--team0", "py:Team,walker")
    assert result.returncode == 2
    assert ("--team0 must be py:SKILL, cpp:SKILL or runswift:SKILL, then any ,KEY=VALUE (got 'py:Team,walker')"
            in result.stderr)
    result = launch("--team1", "runswift:WalkAround")
    assert result.returncode == 2
    assert "--team1 runswift:WalkAround needs --runswift-dir (a rUNSWift behaviours folder)" in result.stderr


def test_walk_engines_are_chosen_per_team_and_known_to_the_shim(tmp_path):
    sys.path.insert(0, str(ROOT / "tools"))
    from launch import WALK_ENGINES, parse_args

    args = parse_args(["--walk-engine1", "nao-joints"])
    assert (args.walk_engine, args.walk_engine0, args.walk_engine1) == ("walkcycle", None, "nao-joints")
    shim_help = subprocess.run([str(ROOT / "build" / "bin" / "robot_shim"), "--help"], capture_output=True,
                               text=True, timeout=30).stdout
    assert all(engine in shim_help for engine in WALK_ENGINES)  # runswift: named in the help of any build
    result = launch("--walk-engine0", "moonwalk")
    assert result.returncode == 2 and "--walk-engine0: invalid choice: 'moonwalk'" in result.stderr
    # A match with each team on another engine plays, and the joint walk moves its robots.
    result = launch("--team-size", 1, "--duration", 4, "--behaviour", "goto", "--walk-engine0", "nao-joints",
                    "--no-log", "--json", tmp_path / "m.json")
    assert result.returncode == 0, result.stderr
    robots = json.loads((tmp_path / "m.json").read_text())["robots"]
    assert all(r["frames_answered"] == 120 for r in robots)


def test_a_match_on_a_changed_field_is_placed_logged_and_drawn_on_that_field(tmp_path):
    result = launch("--team-size", 1, "--duration", 1, "--set", "field.length_mm=7000", "--log-dir", tmp_path)
    assert result.returncode == 0, result.stderr
    assert "field 7000 x 4000 mm" in result.stdout, "the launcher places the robots on the match's field"
    [log] = tmp_path.glob("*.lcmlog")
    first = next(iter(lcm.EventLog(str(log), "r")))
    assert first.channel == "TL_MATCH", "a log reader learns the geometry before anything else"
    sys.path.insert(0, str(ROOT / "viewer"))
    from touchline_viewer.replay_log import ReplayLog
    match = ReplayLog.load(log).match
    assert (match["field"]["length_mm"], match["field"]["width_mm"], match["team_size"]) == (7000, 4000, 1)
