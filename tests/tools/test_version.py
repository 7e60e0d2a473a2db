"""One version, everywhere: the VERSION file is what every program's --version prints, what
CMake's project() was given, and what CITATION.cff and the changelog name."""
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
VERSION = (ROOT / "VERSION").read_text().strip()
PY = sys.executable

PROGRAMS = [
    ("sim_world", [str(BUILD / "bin" / "sim_world")]),
    ("robot_shim", [str(BUILD / "bin" / "robot_shim")]),
    ("touchline_match", [str(BUILD / "bin" / "touchline_match")]),
    ("tools/match", [PY, str(ROOT / "tools" / "launch.py")]),
    ("tools/spy", [str(ROOT / "tools" / "spy")]),
    ("tools/spy", [PY, str(ROOT / "tools" / "spy_text.py")]),
    ("tools/sweep", [PY, str(ROOT / "tools" / "sweep.py")]),
    ("tools/evaluate_teams.py", [PY, str(ROOT / "tools" / "evaluate_teams.py")]),
    ("tools/pushing_calls.py", [PY, str(ROOT / "tools" / "pushing_calls.py")]),
    ("tools/match_stats.py", [PY, str(ROOT / "tools" / "match_stats.py")]),
    ("tools/record_corpus.py", [PY, str(ROOT / "tools" / "record_corpus.py")]),
    ("tools/synthetic_policy.py", [PY, str(ROOT / "tools" / "synthetic_policy.py")]),
    ("touchline_viewer", [PY, "-m", "touchline_viewer"]),
    ("learning/evaluate", [str(ROOT / "learning" / "evaluate")]),
    ("learning/train_tiles", [str(ROOT / "learning" / "train_tiles")]),
    ("learning/train_thesis", [str(ROOT / "learning" / "train_thesis")]),
]


def test_the_version_is_semantic():
    assert re.fullmatch(r"\d+\.\d+\.\d+", VERSION), VERSION


@pytest.mark.parametrize("name, argv", PROGRAMS, ids=[" ".join(a[-1:]) for _, a in PROGRAMS])
def test_every_program_prints_its_name_and_the_version(name, argv):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "viewer")}
    result = subprocess.run([*argv, "--version"], capture_output=True, text=True, timeout=60, env=env)
    assert (result.returncode, result.stdout, result.stderr) == (0, f"{name} {VERSION}\n", "")


def test_cmake_project_version_is_the_file():
    cache = (BUILD / "CMakeCache.txt").read_text()
    assert f"CMAKE_PROJECT_VERSION:STATIC={VERSION}" in cache


def test_citation_and_changelog_name_the_version():
    citation = (ROOT / "CITATION.cff").read_text()  # YAML; read by line, no YAML package needed
    assert f'\nversion: "{VERSION}"\n' in citation and "\nlicense: Apache-2.0\n" in citation
    preferred = citation[citation.index("\npreferred-citation:"):]
    assert "\n  type: thesis\n" in preferred
    assert '\n  title: "Simulation and Behaviour Learning for Robocup SPL"\n' in preferred
    assert f"## [{VERSION}] - " in (ROOT / "CHANGELOG.md").read_text()
    assert "Apache License" in (ROOT / "LICENSE").read_text()[:200]
