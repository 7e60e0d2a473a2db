"""robot_shim's Python options on the command line: usage errors are one line and exit 2;
a module that only fails at import is no usage error (the shim plays on, standing). The
robot's data directory (--data-dir) is where a C++ behaviour finds its policy."""
import os
import secrets
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
ROBOT_SHIM = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build")) / "bin" / "robot_shim"
FIXTURES = Path(__file__).resolve().parent / "fixtures"
ROBOT = ["--team", "0", "--player", "3"]


def run(*args):
    # Without PYTHONDONTWRITEBYTECODE: the shim must keep from writing bytecode by itself.
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.setdefault("TOUCHLINE_MATCH_SECRET", secrets.token_hex(32))
    return subprocess.run([str(ROBOT_SHIM), *map(str, args)], capture_output=True, text=True, timeout=60, env=env)


@pytest.mark.parametrize("args, message", [
    (["--behaviour", "py:nonexistent"], f"no Python module 'nonexistent' in {ROOT / 'behaviour_py'}"),
    (["--behaviour", "py:nonexistent", "--python-dir", FIXTURES], "no Python module 'nonexistent'"),
    (["--behaviour", "py", "--python-dir", "/nonexistent"], "python dir '/nonexistent' is not a directory"),
    (["--behaviour", "py:no_tick", "--python-dir", FIXTURES], "Python module 'no_tick' has no tick(blackboard) function"),
    (["--behaviour", "py:"], "--behaviour py:MODULE needs a module name"),
    (["--behaviour", "py:walker", "--python-dir", FIXTURES, "--param", "forward"], "--param must be key=value"),
    (["--behaviour", "stand", "--data-dir", "/nonexistent"], "--data-dir /nonexistent is not a directory"),
])
def test_bad_python_behaviour_is_one_line_and_exit_2(args, message):
    result = run(*ROBOT, *args)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], result.stderr


def test_help_documents_the_python_behaviour_and_cpu_charging():
    result = run("--help")
    assert result.returncode == 0
    for text in ["--python-dir", "--charge-cpu", "py:MODULE", "robot.params", "0xff00ff", "33.3 ms",
                 "--tick-timeout-ms", "touchline.TickTimeout", "128 + the"]:
        assert text in result.stdout, text
    assert str(ROOT / "behaviour_py") in result.stdout  # the default --python-dir
    assert "--data-dir" in result.stdout and str(ROOT / "config") in result.stdout  # and --data-dir's


def test_a_learned_behaviour_reads_its_policy_from_the_data_dir(tmp_path):
    result = run(*ROBOT, "--behaviour", "LearnedGoToPose", "--data-dir", tmp_path)
    assert result.returncode == 2, result.stderr
    assert result.stderr == (f"robot_shim: {tmp_path}/policies/go_to_pose.policy: cannot read the policy "
                             "(No such file or directory)\n")
    subprocess.run([sys.executable, str(ROOT / "tools" / "synthetic_policy.py"),
                    str(tmp_path / "policies" / "go_to_pose.policy")], check=True)
    # The policy read, the shim starts; no world answers its join here, so it gives up with exit 1.
    result = run(*ROBOT, "--behaviour", "Team", "--param", "walker=learned", "--data-dir", tmp_path,
                 "--lcm-url", "memq://", "--join-timeout", "0.2")
    assert result.returncode == 1, result.stderr
    assert "no sim_world accepted the join" in result.stderr


def test_import_error_at_start_is_no_usage_error(tmp_path):
    # The module exists but does not compile: the shim starts (and would stand, waiting for
    # the fix); here no world answers its join, so it gives up with exit 1, not 2.
    (tmp_path / "behaviour.py").write_text((FIXTURES / "syntax_error.py").read_text())
    result = run(*ROBOT, "--behaviour", "py", "--python-dir", tmp_path, "--lcm-url", "memq://",
                 "--join-timeout", "0.2")
    assert result.returncode == 1, result.stderr
    assert result.stderr.count("SyntaxError") == 1, result.stderr
    assert "robot_shim 0/3: importing behaviour failed (standing, chest LED magenta until fixed):" in result.stderr
    assert "no sim_world accepted the join" in result.stderr
    assert not (tmp_path / "__pycache__").exists()
