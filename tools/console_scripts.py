"""The console scripts `pip install .` makes (pyproject.toml, [project.scripts]): each runs one
tool exactly as `python tools/TOOL.py` does in the source tree (tools/match, tools/sweep), with
the tool's folder (the installed package touchline_tools) first on sys.path, so the tools import
one another by name as they do there.

Reads nothing itself; the tool reads its command line (sys.argv) and exits with its status."""
from __future__ import annotations

import runpy
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def _run(tool: str) -> None:
    if str(HERE) not in sys.path:
        sys.path.insert(0, str(HERE))
    runpy.run_path(str(HERE / tool), run_name="__main__")


def match() -> None:
    """touchline-match: tools/launch.py (tools/match)."""
    _run("launch.py")


def sweep() -> None:
    """touchline-sweep: tools/sweep.py (tools/sweep)."""
    _run("sweep.py")


def spy() -> None:
    """touchline-spy: the bus in this terminal, tools/spy_text.py (tools/spy --text)."""
    _run("spy_text.py")


def evaluate_teams() -> None:
    """touchline-evaluate-teams: tools/evaluate_teams.py."""
    _run("evaluate_teams.py")
