"""The launcher: plays a match, records every message, and stops cleanly on failure (faults and signals:
test_launch_faults.py)."""
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import lcm
from conftest import BUILD, LAUNCH, ROOT
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


def one_line_refusal(result, *needles) -> str:
    """The launcher refused at once: exit code 2, one line on stderr holding every needle, nothing started."""
    assert result.returncode == 2, result.stdout + result.stderr
    [line] = result.stderr.strip().splitlines()
    assert line.startswith("launch: ") and all(n in line for n in needles), line
    assert "Match:" not in result.stdout and "kick-off" not in result.stdout
    return line


def test_a_robot_config_the_robot_refuses_stops_the_launcher_before_anything_starts(tmp_path):
    bad_walk = tmp_path / "walk.ini"
    bad_walk.write_text("[walk]\nperiod_s = -1\n")
    one_line_refusal(launch("--team-size", 1, "--duration", 5, "--walk-config", bad_walk, "--no-log"),
                     "robot_shim", "period_s")


def test_an_unknown_config_key_or_bad_value_is_one_line_at_once():
    one_line_refusal(launch("--set", "rules.nosuch=1"), "the world refuses the match", "rules.nosuch")
    one_line_refusal(launch("--set", "rules.half_s=-5"), "rules.half_s")
    one_line_refusal(launch("--set", "nodot"), "nodot")


def test_an_unknown_skill_or_behaviour_is_one_line_listing_the_known_ones():
    line = one_line_refusal(launch("--team0", "py:NoSuchSkill"), "--team0 py:NoSuchSkill",
                            "unknown Python skill 'NoSuchSkill'")
    assert "known: GoToPose, LearnedGoToPose, GoToBall" in line and "Striker" in line
    one_line_refusal(launch("--skill", "Strikr"), "--skill Strikr", "unknown Python skill 'Strikr'")
    line = one_line_refusal(launch("--team1", "cpp:NoSuch"), "--team1 cpp:NoSuch", "NoSuch")
    assert "Team" in line, "the known C++ behaviours are named: " + line
    one_line_refusal(launch("--team0", "cpp:Team,speed=fast"), "--team0 cpp:Team,speed=fast", "speed")


def fake_build(tmp_path, shim_script: str) -> Path:
    """A build folder with the real sim_world and types but a robot_shim that passes its
    --check and then runs `shim_script` (a fault to inject)."""
    build = tmp_path / "build"
    (build / "bin").mkdir(parents=True)
    (build / "bin" / "sim_world").symlink_to(BUILD / "bin" / "sim_world")
    (build / "lcm_types").symlink_to(BUILD / "lcm_types")
    shim = build / "bin" / "robot_shim"
    shim.write_text(f'#!/bin/sh\nfor a in "$@"; do [ "$a" = --check ] && exec {BUILD}/bin/robot_shim "$@"; done\n'
                    + shim_script)
    shim.chmod(0o755)
    return build


def test_a_robot_that_cannot_start_fails_the_match_and_is_named(tmp_path):
    build = fake_build(tmp_path, 'echo "robot_shim: cannot open the camera" >&2\nexit 1\n')
    result = launch("--build-dir", build, "--team-size", 1, "--duration", 5, "--no-log")
    assert result.returncode == 1, result.stdout + result.stderr
    line = result.stderr.strip().splitlines()[-1]
    assert line.startswith("launch: stopping the match: robot_shim ") and "exited with code 1" in line
    assert "cannot open the camera" in line, line
    assert "Match:" not in result.stdout


def test_the_launcher_offers_every_robot_shim_option_a_match_needs():
    sys.path.insert(0, str(ROOT / "tools"))
    from launch import SHIM_OPTIONS, parse_args

    shim_help = subprocess.run([str(BUILD / "bin" / "robot_shim"), "--help"], capture_output=True, text=True,
                               timeout=30).stdout
    shim_options = set(re.findall(r"^\s+(--[a-z-]+)", shim_help, re.M))
    set_by_launcher = {"--team", "--player", "--behaviour", "--behaviour-plugin", "--param", "--walk-config",
                       "--walk-engine", "--field-config", "--lcm-url", "--data-dir", "--log-level"}
    by_hand_only = {"--help", "--version", "--check", "--secret-file", "--join-timeout", "--world-timeout"}
    offered = {option for option, _ in SHIM_OPTIONS}
    assert shim_options - set_by_launcher - by_hand_only == offered, "robot_shim and tools/match drifted apart"
    args = parse_args(["--python-dir", "/my/behaviour", "--charge-cpu", "--snapshot-every", "0"])
    assert (args.python_dir, args.charge_cpu, args.snapshot_every) == (Path("/my/behaviour"), True, 0)


def test_python_dir_reaches_the_python_robots(tmp_path):
    own = tmp_path / "mine"
    own.mkdir()
    (own / "behaviour.py").write_text(
        "import robot, actioncommand\nSKILL_NAMES = ('Wave',)\n"
        "def tick(blackboard):\n    return actioncommand.compose(leds=actioncommand.leds(0x0000ff))\n")
    one_line_refusal(launch("--python-dir", own, "--skill", "Team"), "unknown Python skill 'Team' (known: Wave)")
    result = launch("--team-size", 1, "--duration", 1, "--python-dir", own, "--skill", "Wave", "--no-log",
                    "--log-level", "debug")
    assert result.returncode == 0, result.stderr
    started = [line for line in result.stdout.splitlines() if line.startswith("launch: started robot_shim")]
    assert len(started) == 2 and all(f"--python-dir {own}" in line for line in started), result.stdout


def test_quiet_and_log_level_govern_the_launchers_lines(tmp_path):
    quiet = launch("--team-size", 1, "--duration", 1, "--behaviour", "goto", "--no-log", "--quiet")
    assert quiet.returncode == 0, quiet.stderr
    assert not [line for line in quiet.stdout.splitlines() if line.startswith("launch:")], quiet.stdout
    assert quiet.stdout.startswith("Match: 1 s simulated"), "the summary is still printed"
    debug = launch("--team-size", 1, "--duration", 1, "--behaviour", "goto", "--no-log", "--log-level", "debug")
    assert "launch: started sim_world (pid " in debug.stdout and "launch: kick-off" in debug.stdout
    assert os.environ.get("TOUCHLINE_MATCH_SECRET", "no secret") not in debug.stdout
    result = launch("--log-level", "loud")
    assert result.returncode == 2 and "--log-level: invalid choice: 'loud'" in result.stderr


def test_off_a_terminal_progress_is_a_line_every_tenth_of_the_planned_match():
    # A whole refereed match, short: two halves of INITIAL 0 s, READY 1 s, SET 1 s, PLAYING 5 s.
    short = ("--set", "rules.initial_s=0", "--set", "rules.ready_s=1", "--set", "rules.set_s=1",
             "--set", "rules.half_s=5")
    result = launch("--team-size", 1, "--behaviour", "goto", "--no-log", *short)
    assert result.returncode == 0, result.stderr
    lines = [line for line in result.stdout.splitlines() if " % of the match" in line]
    percents = [int(line.split(" %")[0].split()[-1]) for line in lines]
    assert percents == sorted(percents) and len(percents) >= 5 and percents[-1] == 100, result.stdout
    assert "of 14 s simulated" in lines[-1], "the total is the planned length, 2 x (0 + 1 + 1 + 5) s"
    assert any(line.startswith("Match: 14 s simulated") for line in result.stdout.splitlines()), result.stdout
    none = launch("--team-size", 1, "--behaviour", "goto", "--no-log", "--no-progress", *short)
    assert none.returncode == 0 and " % of the match" not in none.stdout


def test_each_goal_adds_its_stoppage_to_the_total_so_a_whole_match_still_ends_at_100_percent():
    # A striker against a standing robot scores twice (seed 1, at 0:28 and 1:04); READY 2 s and
    # SET 1 s again after each.
    result = launch("--team-size", 1, "--team0", "cpp:Striker", "--team1", "cpp:stand", "--no-log",
                    "--set", "rules.initial_s=0", "--set", "rules.ready_s=2", "--set", "rules.set_s=1",
                    "--set", "rules.half_s=30")
    assert result.returncode == 0, result.stderr
    [goal] = [line for line in result.stdout.splitlines() if line.startswith("Goals: ")]
    assert goal.count(" at ") == 2, goal
    lines = [line for line in result.stdout.splitlines() if " % of the match" in line]
    assert "of 66 s simulated" in lines[0] and "score 0:0" in lines[0], "before the goals: 2 x (0 + 2 + 1 + 30) s"
    assert any("of 69 s simulated" in line and "score 1:0" in line for line in lines), result.stdout
    assert "100 % of the match, 72 of 72 s simulated" in lines[-1], result.stdout
    assert any(line.startswith("Match: 72 s simulated") for line in result.stdout.splitlines())


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
    result = launch("--live-robot-timeout-ms", -5)
    assert result.returncode == 2 and "--live-robot-timeout-ms must be > 0" in result.stderr


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
    assert team_behaviour("plugin:/teams/libours.so:ChaseBall,speed=0.5") == [
        "--behaviour-plugin", "/teams/libours.so", "--behaviour", "ChaseBall", "--param", "speed=0.5"]
    assert team_behaviour("plugin:libours.so:ChaseBall")[1] == str(Path("libours.so").resolve())
    for bad in ("Team", "java:Team", "py:", "py:Team,walker", "py:Team,=x", "py:a:b", "runswift:", "plugin:x.so",
                "plugin::Chase", "plugin:x.so:"):
        assert team_behaviour(bad) is None, bad
    result = launch("--team0", "py:Team,walker")
    assert result.returncode == 2
    assert ("--team0 must be py:SKILL, cpp:SKILL, runswift:SKILL or plugin:PATH:NAME, then any ,KEY=VALUE "
            "(got 'py:Team,walker')"
            in result.stderr)
    result = launch("--team1", "runswift:WalkAround")
    assert result.returncode == 2
    assert "--team1 runswift:WalkAround needs --runswift-dir (a rUNSWift behaviours folder)" in result.stderr


def test_a_python_teams_bad_parameter_stops_the_match_before_it_starts():
    # behaviour.py's check_params, called by robot_shim --check and by touchline_match as it makes the robots.
    for mode in ([], ["--in-process"]):
        result = launch("--team1", "py:Team,supporters=best", "--no-log", *mode)
        assert result.returncode == 2, (mode, result.stderr)
        assert "Team: parameter supporters must be tuned or thesis (got 'best')" in result.stderr, (mode, result.stderr)
        assert "PLAYING" not in result.stdout, mode


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
