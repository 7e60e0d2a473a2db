"""examples/behaviour_plugin as a team uses it: Touchline installed (cmake --install) to a
prefix, the example built outside the tree with find_package(Touchline) against that prefix
only, and its ChaseBall played from the installed programs: by robot_shim processes in a
lockstep match (tools/launch.py --build-dir PREFIX --team0 plugin:PATH:NAME) and in process
by touchline_match, the same match. A library that is missing, is no library, or refuses the
name or a parameter: one line and exit code 2. Runs in a private network namespace
(tools/netns)."""
import json
import math
import os
import secrets
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
CMAKE = os.environ.get("TOUCHLINE_CMAKE", "cmake")
STEP_S = 300  # a wall-clock bound that only turns a hang into a failure
# Short READY and SET, so 20 s of match are mostly PLAYING (ChaseBall stands before that).
MATCH = ["--team-size", "1", "--duration", "20", "--set", "rules.ready_s=1", "--set", "rules.set_s=1", "--seed", "3"]
os.environ.setdefault("TOUCHLINE_MATCH_SECRET", secrets.token_hex(32))


def run(*args, **kw):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=STEP_S, **kw)


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(prefix, library): Touchline installed and the example built against it."""
    tmp = tmp_path_factory.mktemp("plugin")
    prefix, example = tmp / "prefix", tmp / "example"
    result = run(CMAKE, "--install", BUILD, "--prefix", prefix)
    assert result.returncode == 0, result.stdout + result.stderr
    # Only the prefix: the example must not find this build tree's package or headers.
    result = run(CMAKE, "-S", ROOT / "examples" / "behaviour_plugin", "-B", example, "-DCMAKE_BUILD_TYPE=Release",
                 f"-DCMAKE_PREFIX_PATH={prefix}", f"-DCMAKE_CXX_COMPILER={os.environ.get('TOUCHLINE_CXX', 'c++')}",
                 "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON")
    assert result.returncode == 0, result.stdout + result.stderr
    result = run(CMAKE, "--build", example)
    assert result.returncode == 0, result.stdout + result.stderr
    library = example / "libchase_ball.so"
    assert library.is_file()
    return prefix, library


def launch(prefix, out, *args):
    result = run(sys.executable, ROOT / "tools" / "launch.py", "--build-dir", prefix, "--no-log", "--no-progress",
                 *MATCH, *args, "--json", out)
    assert result.returncode == 0, result.stdout + result.stderr
    return json.loads(out.read_text())


def distance_to_ball(summary, team):
    robot = next(r for r in summary["robots"] if r["team"] == team)
    return math.hypot(robot["x_mm"] - summary["ball"]["x_mm"], robot["y_mm"] - summary["ball"]["y_mm"])


def test_the_installed_package_has_what_a_team_needs(installed):
    prefix, _ = installed
    for path in ("bin/robot_shim", "bin/sim_world", "bin/touchline_match", "include/touchline/robot_api/plugin.hpp",
                 "include/touchline/robot_api/blackboard.hpp", "include/touchline/act_t.hpp",
                 "share/touchline/lcm_types/act_t.lcm", "share/touchline/lcm_types/python/touchline/act_t.py",
                 "lib/cmake/Touchline/TouchlineConfig.cmake", "lib/cmake/Touchline/TouchlineConfigVersion.cmake"):
        assert (prefix / path).is_file(), path
    version = (ROOT / "VERSION").read_text().strip()
    assert run(prefix / "bin" / "robot_shim", "--version").stdout.split()[-1] == version


def test_robot_shim_plays_the_teams_behaviour_and_it_chases_the_ball(installed, tmp_path):
    prefix, library = installed
    summary = launch(prefix, tmp_path / "lockstep.json", "--team0", f"plugin:{library}:ChaseBall,speed=1",
                     "--team1", "cpp:stand")
    assert summary["mode"] == "lockstep"
    assert [r["frames_answered"] for r in summary["robots"]] == [600, 600]
    # Both start at their kick-off corners, about 3 m from the ball: ChaseBall walks up to it,
    # the tree's stand stays.
    assert distance_to_ball(summary, 0) < 1000
    assert distance_to_ball(summary, 1) > 2000
    # In process (touchline_match, the same robot options): the same match, bit for bit.
    in_process = launch(prefix, tmp_path / "in_process.json", "--team0", f"plugin:{library}:ChaseBall,speed=1",
                        "--team1", "cpp:stand", "--in-process")
    assert in_process["truth_hash"] == summary["truth_hash"]


@pytest.mark.parametrize("plugin, behaviour, message", [
    ("{library}", "Chase", "--behaviour-plugin {library}: unknown behaviour 'Chase' (this library has ChaseBall)"),
    ("{library}", "ChaseBall --param speed=2",
     "--behaviour-plugin {library}: ChaseBall: speed must be a number in (0, 1] (got '2')"),
    ("{library}", "py", "--behaviour-plugin makes C++ behaviours: --behaviour py names the Python one (see --help)"),
    ("{prefix}/nope.so", "ChaseBall", "--behaviour-plugin {prefix}/nope.so: no such file"),
    ("{prefix}/lib/cmake/Touchline/TouchlineConfig.cmake", "ChaseBall",
     "--behaviour-plugin {prefix}/lib/cmake/Touchline/TouchlineConfig.cmake: cannot load: "),
])
def test_a_bad_library_is_one_line_and_exit_2(installed, plugin, behaviour, message):
    prefix, library = installed
    plugin, message = (s.format(library=library, prefix=prefix) for s in (plugin, message))
    robot = ["--team", "0", "--player", "1", "--behaviour-plugin", plugin, "--behaviour", *behaviour.split()]
    for program, args, prefix_line in (("robot_shim", ["--check", *robot], "robot_shim: "),
                                       ("touchline_match", ["--duration", "1", "--", *robot], "touchline_match: ")):
        result = run(prefix / "bin" / program, *args)
        assert result.returncode == 2, (program, result.stderr)
        lines = result.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith(prefix_line) and message in lines[0], (program, lines)
