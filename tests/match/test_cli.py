"""Bad input to either program: one clear line on stderr and exit code 2."""
import subprocess

import pytest

from touchline_harness import ROBOT_SHIM, ROOT, SIM_WORLD


def run(*args):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=30)


@pytest.mark.parametrize("args, message", [
    (["--mode", "bogus"], "--mode must be lockstep, realtime or free (got 'bogus')"),
    (["--robots", "9"], "--robots must be 1..8"),
    (["--speed", "0"], "--speed must be > 0"),
    (["--config", "/nonexistent.ini"], "/nonexistent.ini: cannot open config file"),
    (["--set", "match.team_size=9"], "match.team_size"),
    (["--set", "field.nonsense=1"], "nonsense"),
    (["--frobnicate"], "unrecognised option '--frobnicate'"),
])
def test_sim_world_rejects_bad_options(args, message):
    result = run(SIM_WORLD, *args)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr


@pytest.mark.parametrize("args, message", [
    (["--player", "1"], "--team"),
    (["--team", "2", "--player", "1"], "--team must be 0 or 1 (got 2)"),
    (["--team", "0", "--player", "8"], "--player must be 1..7 (got 8)"),
    (["--team", "0", "--player", "1", "--behaviour", "nope"], "unknown behaviour 'nope'"),
    (["--team", "0", "--player", "1", "--behaviour", "goto", "--param", "x=abc"], "parameter x must be a number"),
    (["--team", "0", "--player", "1", "--walk-config", "/nonexistent.ini"], "cannot open config file"),
])
def test_robot_shim_rejects_bad_options(args, message):
    result = run(ROBOT_SHIM, *args)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr


def test_help_documents_every_option():
    world = run(SIM_WORLD, "--help")
    shim = run(ROBOT_SHIM, "--help")
    assert world.returncode == 0 and shim.returncode == 0
    for option in ["--config", "--set", "--robots", "--duration", "--mode", "--speed", "--robot-timeout-ms",
                   "--seed", "--lcm-url", "--summary"]:
        assert option in world.stdout
    for option in ["--team", "--player", "--behaviour", "--param", "--walk-config", "--lcm-url"]:
        assert option in shim.stdout
    assert "goto" in shim.stdout


def test_shipped_configs_load(tmp_path):
    for config in ["spl2011.ini", "spl2020.ini"]:
        # --robots 1 and a tiny join timeout: the config is read before anything waits.
        result = run(SIM_WORLD, "--config", ROOT / "config" / config, "--robots", "1", "--join-timeout", "0.01",
                     "--lcm-url", "memq://")
        assert result.returncode == 1 and "only 0 of 1 robots joined" in result.stderr, result.stderr
