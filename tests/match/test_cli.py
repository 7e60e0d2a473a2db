"""Bad input to either program: one clear line on stderr and exit code 2, at once (no core
dump, no hang, nothing learned only after a match). Runs in a private network namespace
(tools/netns), so the LCM URLs tried here reach nothing but this namespace's loopback."""
import json
import shutil
import subprocess

import pytest

from touchline_harness import ROBOT_SHIM, ROOT, SIM_WORLD

HANG_S = 10  # a bad input must be refused at once; this only turns a hang into a failure
MAX_U64 = "18446744073709551615"


def run(*args, **kwargs):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=HANG_S, **kwargs)


def expect_usage_error(result, message):
    assert result.returncode == 2, (result.returncode, result.stderr)  # not 134: no abort, no core
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr


@pytest.mark.parametrize("args, message", [
    (["--mode", "bogus"], "--mode must be lockstep, realtime or free (got 'bogus')"),
    (["--log-level", "loud"], "--log-level loud: not a level (trace, debug, info, warning, error, off)"),
    (["--robots", "9"], "--robots must be 1..8"),
    (["--robots", "-3"], "--robots must be an integer in [1, 14] (got '-3')"),
    (["--speed", "0"], "--speed must be a number in [0.01, 1000] (got '0')"),
    (["--speed", "nan"], "--speed must be a number in [0.01, 1000] (got 'nan')"),
    (["--speed", "1e308"], "--speed must be a number in [0.01, 1000] (got '1e308')"),
    (["--join-timeout", "nan"], "--join-timeout must be a number in [0.01, 86400] (got 'nan')"),
    (["--join-timeout", "1e300"], "--join-timeout must be a number in [0.01, 86400] (got '1e300')"),
    (["--robot-timeout-ms", "nan"], "--robot-timeout-ms must be an integer in [1, 3600000] (got 'nan')"),
    (["--robot-timeout-ms", "99999999999999999999"], "--robot-timeout-ms must be an integer in [1, 3600000]"),
    (["--robot-timeout-ms", "0"], "--robot-timeout-ms must be an integer in [1, 3600000] (got '0')"),
    (["--duration", "inf"], "--duration must be a number in [0.001, 1000000000] (got 'inf')"),
    (["--seed", "-1"], f"--seed must be an integer in [0, {MAX_U64}] (got '-1')"),  # once wrapped to 2^64-1
    (["--seed", "7x"], f"--seed must be an integer in [0, {MAX_U64}] (got '7x')"),
    (["--seed", "18446744073709551616"], f"--seed must be an integer in [0, {MAX_U64}]"),
    (["--config", "/nonexistent.ini"], "/nonexistent.ini: cannot open config file (No such file or directory)"),
    (["--config", ROOT / "config"], f"{ROOT / 'config'}: cannot open config file (it is a directory)"),
    (["--set", "match.team_size=9"], "match.team_size"),
    (["--set", "field.nonsense=1"], "nonsense"),
    (["--set", "field.length_mm=inf"], "field.length_mm must be a finite number (got 'inf')"),  # once SIGABRT
    (["--set", "physics.ball_mass_kg=inf"], "physics.ball_mass_kg must be a finite number (got 'inf')"),
    (["--set", "field.length_mm=1e30"], "field.length_mm must be in (0, 30000] (got 1e+30)"),
    (["--summary", "/nonexistent/summary.json"],
     "--summary /nonexistent/summary.json: cannot write there (No such file or directory)"),
    (["--summary", "/tmp"], "--summary /tmp: cannot write there (it is a directory)"),
    (["--log", "/nonexistent/match.lcmlog"], "--log /nonexistent/match.lcmlog: cannot write there"),
    (["--lcm-url", "udpm://8.8.8.8:7667"],
     "--lcm-url 'udpm://8.8.8.8:7667': cannot open LCM: not a multicast group address: 8.8.8.8"),
    (["--lcm-url", "tcpq://127.0.0.1:1"],  # once an abort, after three lines per attempt
     "--lcm-url 'tcpq://127.0.0.1:1': cannot open LCM: lcm_tcpq connect: Connection refused"),
    (["--lcm-url", "bogus://x"], "cannot open LCM: LCM provider \"bogus\" not found"),
    (["--lcm-url", "udpm://239.255.76.67:7667?ttl=abc"], "cannot open LCM: Invalid value for ttl"),
    # The robots use the two ports above the URL's (bridge/lcm lanes.hpp): 65534 has one.
    (["--lcm-url", "udpm://239.255.76.67:65534?ttl=0"], "cannot open LCM: a udpm URL needs a port below 65534"),
    (["--frobnicate"], "unrecognised option '--frobnicate'"),
])
def test_sim_world_rejects_bad_options(args, message):
    expect_usage_error(run(SIM_WORLD, *args), message)


SHIM = ["--team", "0", "--player", "1"]


@pytest.mark.parametrize("args, message", [
    (["--player", "1"], "--team"),
    (["--team", "2", "--player", "1"], "--team must be an integer in [0, 1] (got '2')"),
    (["--team", "0", "--player", "1", "--log-level", "loud"], "--log-level loud: not a level ("),
    (["--team", "-1", "--player", "1"], "--team must be an integer in [0, 1] (got '-1')"),
    (["--team", "0", "--player", "8"], "--player must be an integer in [1, 7] (got '8')"),
    (["--team", "0", "--player", "99999999999"], "--player must be an integer in [1, 7]"),
    (SHIM + ["--behaviour", "nope"], "unknown behaviour 'nope'"),
    (SHIM + ["--behaviour", "goto", "--param", "x=abc"], "parameter x must be a number"),
    (SHIM + ["--walk-config", "/nonexistent.ini"], "cannot open config file (No such file or directory)"),
    (SHIM + ["--walk-config", ROOT / "config"], f"{ROOT / 'config'}: cannot open config file (it is a directory)"),
    (SHIM + ["--walk-engine", "moonwalk"], "--walk-engine: unknown walk engine 'moonwalk' (walkcycle, nao-joints"),
    (SHIM + ["--kick-config", ROOT / "config"], f"{ROOT / 'config'}: cannot open config file (it is a directory)"),
    (SHIM + ["--field-config", ROOT / "config"], f"{ROOT / 'config'}: cannot open config file (it is a directory)"),
    (SHIM + ["--join-timeout", "nan"], "--join-timeout must be a number in [0.01, 86400] (got 'nan')"),
    (SHIM + ["--join-timeout", "-1"], "--join-timeout must be a number in [0.01, 86400] (got '-1')"),
    (SHIM + ["--world-timeout", "1e300"], "--world-timeout must be a number in [0.01, 86400] (got '1e300')"),
    (SHIM + ["--world-timeout", "inf"], "--world-timeout must be a number in [0.01, 86400] (got 'inf')"),
    (SHIM + ["--snapshot-every", "-1"], "--snapshot-every must be an integer in [0, 1000000] (got '-1')"),
    (SHIM + ["--tick-timeout-ms", "nan"], "--tick-timeout-ms must be an integer in [0, 3600000] (got 'nan')"),
    (SHIM + ["--tick-timeout-ms", "-1"], "--tick-timeout-ms must be an integer in [0, 3600000] (got '-1')"),
    (SHIM + ["--lcm-url", "udpm://8.8.8.8:7667"], "cannot open LCM: not a multicast group address: 8.8.8.8"),
    (SHIM + ["--lcm-url", "tcpq://127.0.0.1:1"], "cannot open LCM: lcm_tcpq connect: Connection refused"),
])
def test_robot_shim_rejects_bad_options(args, message):
    expect_usage_error(run(ROBOT_SHIM, *args), message)


@pytest.mark.parametrize("program", [[SIM_WORLD], [ROBOT_SHIM, *SHIM]])
def test_no_multicast_route_is_one_line_not_lcms_advice(program):
    # A namespace of its own with no route at all: LCM printed 14 lines of advice about
    # ifconfig and route, and the program one more.
    if not shutil.which("unshare") or run("unshare", "--net", "true").returncode != 0:
        pytest.skip("cannot make a network namespace here")
    result = run("unshare", "--net", *program, "--lcm-url", "udpm://239.255.76.67:7667?ttl=0")
    expect_usage_error(result, "--lcm-url 'udpm://239.255.76.67:7667?ttl=0': cannot open LCM: no multicast route")


def test_summary_is_checked_at_start_and_a_failed_run_leaves_no_file(tmp_path):
    summary = tmp_path / "summary.json"
    # No robot joins, so the run fails before the match; the path was fine, so no usage error.
    result = run(SIM_WORLD, "--robots", "1", "--join-timeout", "0.1", "--lcm-url", "memq://", "--summary", summary)
    assert result.returncode == 1 and "only 0 of 1 robots joined" in result.stderr, result.stderr
    assert not summary.exists()  # checked by creating it, then removed: no stray empty file
    summary.write_text("an earlier match's summary\n")
    result = run(SIM_WORLD, "--robots", "1", "--join-timeout", "0.1", "--lcm-url", "memq://", "--summary", summary)
    assert result.returncode == 1, result.stderr
    assert summary.read_text() == "an earlier match's summary\n"  # an existing file is left alone


def test_help_documents_every_option():
    world = run(SIM_WORLD, "--help")
    shim = run(ROBOT_SHIM, "--help")
    assert world.returncode == 0 and shim.returncode == 0
    for option in ["--config", "--set", "--robots", "--duration", "--mode", "--speed", "--robot-timeout-ms",
                   "--join-timeout", "--seed", "--lcm-url", "--summary", "--log"]:
        assert option in world.stdout
    for option in ["--team", "--player", "--behaviour", "--param", "--walk-config", "--walk-engine", "--lcm-url",
                   "--join-timeout",
                   "--world-timeout", "--tick-timeout-ms"]:
        assert option in shim.stdout
    assert "goto" in shim.stdout


def test_shipped_configs_load(tmp_path):
    for config in ["spl2011.ini", "spl2020.ini"]:
        # --robots 1 and a tiny join timeout: the config is read before anything waits.
        result = run(SIM_WORLD, "--config", ROOT / "config" / config, "--robots", "1", "--join-timeout", "0.01",
                     "--lcm-url", "memq://")
        assert result.returncode == 1 and "only 0 of 1 robots joined" in result.stderr, result.stderr


def test_check_modes_judge_a_match_without_playing_it():
    # sim_world --check: the world's config with every --set, its planned length, nothing waited for.
    result = run(SIM_WORLD, "--check", "--config", ROOT / "config" / "spl2020.ini", "--set", "rules.half_s=300",
                 "--set", "rules.standby_s=10")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == {"planned_s": 722, "goal_stoppage_s": 50, "duration_s": 3600, "team_size": 5,
                                         "field_length_mm": 9000, "field_width_mm": 6000}
    assert json.loads(run(SIM_WORLD, "--check", "--duration", 60).stdout)["planned_s"] == 60
    assert json.loads(run(SIM_WORLD, "--check", "--set", "rules.referee=false").stdout)["planned_s"] == 3600
    expect_usage_error(run(SIM_WORLD, "--check", "--set", "rules.nosuch=1"),
                       "unrecognised option 'rules.nosuch' (the keys of [rules]: referee,")
    # robot_shim --check: options, config files and a C++ behaviour with its parameters.
    assert run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "Team", "--param", "walker=learned").returncode == 0
    assert run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "py").stdout == ""
    expect_usage_error(run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "Team", "--param", "speed=fast"),
                       "Team: unknown parameter 'speed'")
    # A Python behaviour is imported and its check_params(params) judges the parameters.
    expect_usage_error(run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "py", "--param", "skill=Team", "--param",
                           "walker=neural"), "Team: parameter walker must be hand or learned (got 'neural')")
    expect_usage_error(run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "py", "--param", "skill=Nope"),
                       "unknown skill 'Nope' (known: GoToPose,")
    expect_usage_error(run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "nope"),
                       "unknown behaviour 'nope' (known: stand, walk, goto,")
    expect_usage_error(run(ROBOT_SHIM, *SHIM, "--check", "--behaviour", "py", "--python-dir", "/nonexistent"),
                       "--python-dir /nonexistent is not a directory")
