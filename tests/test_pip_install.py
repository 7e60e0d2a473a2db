"""`pip install .` as a user does it (pyproject.toml, scikit-build-core through the top-level
CMakeLists.txt), into a fresh venv, reusing this build folder (pip install --no-build-isolation
-C build-dir=BUILD: nothing is compiled twice). Then from another directory, with no PYTHONPATH
and none of Touchline's variables: the console scripts answer --version, touchline-match plays a
short 1 v 1 match in process that is the build tree's match (same seed, same truth hash), the
installed programs default to the venv's share/touchline/ (not the source tree), every
Python package imports from the venv, and a team's library built against the venv's CMake
package on our C++ skills (touchline::behaviour_cpp) plays as the built-in ones do.

The fresh venv takes its third-party packages (lcm, numpy, ..., and the build backend
scikit-build-core) from the environment running this test, through a .pth file: no network
and no download, and nothing of Touchline's comes from there (checked)."""
import json
import os
import site
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BUILD = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
VERSION = (ROOT / "VERSION").read_text().strip()
STEP_S = 600  # a wall-clock bound that only turns a hang into a failure
PACKAGES = ("touchline", "touchline_tools", "touchline_viewer", "touchline_rl", "touchline_paths", "touchline_sim",
            "robot")
# Short READY and SET, so the match is mostly PLAYING.
MATCH = ["--team-size", "1", "--duration", "10", "--seed", "3", "--no-log", "--no-progress", "--in-process",
         "--set", "rules.ready_s=1", "--set", "rules.set_s=1"]
CMAKE = os.environ.get("TOUCHLINE_CMAKE", "cmake")
# A team's library of our skills: robot_shim --behaviour-plugin PATH --behaviour NAME makes NAME
# with touchline::behaviour_cpp's registry, as --behaviour NAME does inside the programs.
PLUGIN_CMAKE = """cmake_minimum_required(VERSION 3.22)
project(our_skills LANGUAGES CXX)
find_package(Touchline REQUIRED)
touchline_add_behaviour_plugin(our_skills our_skills.cpp)
target_link_libraries(our_skills PRIVATE touchline::behaviour_cpp)
"""
PLUGIN_CPP = """#include <touchline/behaviour/registry.hpp>
#include <touchline/robot_api/plugin.hpp>
std::unique_ptr<touchline::api::Behaviour> make(const touchline::api::PluginRequest& request) {
  return touchline::behaviour::make_behaviour(request.name, request.params);
}
TOUCHLINE_BEHAVIOUR_PLUGIN(make)
"""


def run(args, **kw):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=STEP_S, **kw)


def third_party_dirs() -> list[str]:
    """The site-packages folders this interpreter imports from (its own and any a .pth adds)."""
    dirs = {str(Path(p).resolve()) for p in [*site.getsitepackages(), *sys.path]
            if Path(p).name in ("site-packages", "dist-packages") and Path(p).is_dir()}
    return sorted(dirs)


@pytest.fixture(scope="module")
def venv(tmp_path_factory):
    """A fresh venv with this tree pip-installed into it."""
    try:
        import scikit_build_core  # noqa: F401
    except ImportError:
        pytest.fail("scikit-build-core (the build backend) is missing here: tools/setup installs it "
                    "(tools/requirements.txt)")
    tmp = tmp_path_factory.mktemp("pip")
    venv = tmp / "venv"
    result = run([sys.executable, "-m", "venv", venv])
    assert result.returncode == 0, result.stderr
    deps = third_party_dirs()
    for d in deps:  # what the .pth brings is only third-party
        assert not [p for p in Path(d).iterdir() if p.name.startswith(("touchline", "robot."))], d
    (site_dir,) = (venv / "lib").glob("python3*/site-packages")
    (site_dir / "touchline-test-deps.pth").write_text("\n".join(deps) + "\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH" and not k.startswith(("TOUCHLINE_", "SKBUILD"))}
    result = run([venv / "bin" / "python", "-m", "pip", "install", "--no-index", "--no-deps", "--no-build-isolation",
                  "--disable-pip-version-check", "-C", f"build-dir={BUILD}", "-C", "cmake.python-hints=false", ROOT],
                 env=env, cwd=tmp)
    assert result.returncode == 0, result.stdout[-5000:] + result.stderr[-5000:]
    return venv


@pytest.fixture
def user(venv, tmp_path):
    """How a user runs it: from a directory of their own, the venv's bin/ on PATH, no PYTHONPATH."""
    env = {"PATH": f"{venv / 'bin'}:/usr/bin:/bin", "HOME": str(tmp_path), "LANG": "C.UTF-8"}
    return lambda *args: run(args, env=env, cwd=tmp_path)


def test_every_console_script_answers_version(user):
    for script in ("touchline-match", "touchline-sweep", "touchline-spy", "touchline-evaluate-teams",
                   "touchline-viewer"):
        result = user(script, "--version")
        assert result.returncode == 0, script + ": " + result.stderr
        assert result.stdout.split()[-1] == VERSION, script
    result = user("touchline-viewer-export", "--help")  # it has no --version (yet)
    assert result.returncode == 0 and "--log" in result.stdout, result.stderr


def test_the_installed_match_is_the_build_trees_match(user, venv, tmp_path):
    result = user("touchline-match", *MATCH, "--json", "installed.json")
    assert result.returncode == 0, result.stdout + result.stderr
    installed = json.loads((tmp_path / "installed.json").read_text())
    assert installed["mode"] == "in-process"
    assert [(r["team"], r["player"]) for r in installed["robots"]] == [(0, 1), (1, 1)]
    assert installed["frames"] == 300 and all(r["frames_answered"] == 300 for r in installed["robots"])
    # The build tree's programs and launcher, the same match: the same truth, bit for bit.
    assert installed["truth_hash"] == tree_match(tmp_path)["truth_hash"]


def tree_match(tmp_path, *args):
    """The summary of MATCH played by the build tree's launcher and programs."""
    out = tmp_path / "tree.json"
    result = run([sys.executable, ROOT / "tools" / "launch.py", "--build-dir", BUILD, *MATCH, *args, "--json", out])
    assert result.returncode == 0, result.stdout + result.stderr
    return json.loads(out.read_text())


def test_a_teams_library_of_our_cpp_skills_plays_as_the_built_in_ones(user, venv, tmp_path):
    source, build = tmp_path / "our_skills", tmp_path / "our_skills_build"
    source.mkdir()
    (source / "CMakeLists.txt").write_text(PLUGIN_CMAKE)
    (source / "our_skills.cpp").write_text(PLUGIN_CPP)
    # Only the venv: not this build tree's package or headers.
    result = run([CMAKE, "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={venv}",
                  f"-DCMAKE_CXX_COMPILER={os.environ.get('TOUCHLINE_CXX', 'c++')}",
                  "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"])
    assert result.returncode == 0, result.stdout + result.stderr
    result = run([CMAKE, "--build", build])
    assert result.returncode == 0, result.stdout + result.stderr
    library = build / "libour_skills.so"
    result = user("touchline-match", *MATCH, "--team0", f"plugin:{library}:Team", "--team1", "cpp:Team",
                  "--json", "plugin.json")
    assert result.returncode == 0, result.stdout + result.stderr
    plugin = json.loads((tmp_path / "plugin.json").read_text())
    assert plugin["truth_hash"] == tree_match(tmp_path, "--team0", "cpp:Team", "--team1", "cpp:Team")["truth_hash"]


def test_the_installed_programs_play_from_the_venvs_files(user, venv):
    share = venv / "share" / "touchline"
    for path in ("behaviour_py/behaviour.py", "config/spl2011.ini", "config/walk.ini", "viewer/static", "VERSION"):
        assert (share / path).exists(), path
    for program in ("sim_world", "robot_shim", "touchline_match"):
        assert (venv / "bin" / program).is_file(), program
    # Its robots' defaults (touchline_match's robots take the same options) name the venv's
    # copies, not the source tree's folders the programs were built beside.
    result = user("robot_shim", "--help")
    assert result.returncode == 0, result.stderr
    assert f'--python-dir arg (={share / "behaviour_py"})' in result.stdout
    assert f'--data-dir arg (={share / "config"})' in result.stdout


def test_every_package_imports_from_the_venv(user, venv):
    code = ("import importlib, json; print(json.dumps({m: importlib.import_module(m).__file__ for m in %r}))"
            % (PACKAGES,))
    result = user(venv / "bin" / "python", "-c", code)
    assert result.returncode == 0, result.stderr
    for module, path in json.loads(result.stdout).items():
        assert Path(path).resolve().is_relative_to(venv.resolve()), (module, path)
    result = user(venv / "bin" / "python", "-c", "import touchline_paths; print(touchline_paths.PREFIX, "
                  "touchline_paths.behaviour_py(), touchline_paths.ROOT)")
    assert result.stdout.split() == [str(venv), str(venv / "share" / "touchline" / "behaviour_py"), "None"]


def test_the_viewer_serves_and_learning_steps_from_the_venvs_files(user, venv):
    result = user(venv / "bin" / "python", "-c", "from touchline_viewer import server; print(server.STATIC)")
    assert result.returncode == 0, result.stderr
    assert Path(result.stdout.strip()) == venv / "share" / "touchline" / "viewer" / "static"
    assert (Path(result.stdout.strip()) / "index.html").is_file()
    # The environment runs the installed touchline_sim and reads the installed behaviour_py's
    # policy code (touchline_rl.robot_skills).
    code = ("import gymnasium, touchline_rl; env = gymnasium.make('Touchline/GoToPose-v0'); env.reset(seed=1); "
            "print(len(env.step(0)))")
    result = user(venv / "bin" / "python", "-c", code)
    assert (result.returncode, result.stdout.strip()) == (0, "5"), result.stderr
