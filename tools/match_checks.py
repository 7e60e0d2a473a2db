"""The launcher's checks before anything starts: every bad input of a match (a --set key or
value the world does not know, a behaviour or skill no robot has, a config file a robot
refuses) ends the launcher at once with one line and exit code 2, instead of a stall, a
shim's failure or a robot standing through a whole match.

The programs judge their own options (one source of truth): `sim_world --check` loads the
world config with every --set through the world's own loader and prints the match's planned
length (read here for the progress bar); `robot_shim --check` makes the behaviour with its
parameters (a Python module's optional check_params(params) judges them) and reads the
robot's config files. A Python skill's name is also checked here, first and in either mode,
against the SKILL_NAMES of the Python behaviour's behaviour.py (behaviour_py/behaviour.py, or
--python-dir's), read without importing it, so the refusal lists the known skills; in process
no robot_shim runs, and touchline_match judges the rest of the parameters as it starts.
"""
from __future__ import annotations

import ast
import json
import os
import secrets
import subprocess
from dataclasses import dataclass
from pathlib import Path

from match_processes import SECRET_ENV

CHECK_TIMEOUT_S = 60  # wall seconds a program's --check may take (a loaded machine, a large policy)


class BadInput(Exception):
    """One line for the user: what is wrong and what would be right."""


@dataclass
class MatchPlan:
    """How long the match is planned to last, in simulated seconds (sim_world --check)."""
    planned_s: float        # two halves with their INITIAL, READY, SET and half-time, capped at duration_s
    goal_stoppage_s: float  # READY and SET again after each goal
    duration_s: float       # the cap: match.duration_s or --duration


def run_check(program: Path, argv: list, what: str) -> str:
    """`program --check argv...`'s stdout; BadInput with its one-line error if it refuses."""
    env = {**os.environ, SECRET_ENV: os.environ.get(SECRET_ENV) or secrets.token_hex(32)}
    try:
        result = subprocess.run([str(program), "--check", *map(str, argv)], capture_output=True, text=True,
                                env=env, timeout=CHECK_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        raise BadInput(f"{what}: {program.name} --check took over {CHECK_TIMEOUT_S} s") from None
    if result.returncode != 0:
        lines = result.stderr.strip().splitlines() or [f"{program.name} --check exited with code {result.returncode}"]
        raise BadInput(f"{what}: {lines[-1]}")
    return result.stdout


def check_world(bin_world: Path, world_argv: list) -> MatchPlan:
    """The world's options and config as the match would start it; its planned length."""
    plan = json.loads(run_check(bin_world, world_argv, "the world refuses the match").strip().splitlines()[-1])
    return MatchPlan(float(plan["planned_s"]), float(plan["goal_stoppage_s"]), float(plan["duration_s"]))


def python_skills(python_dir: Path) -> tuple[str, ...] | None:
    """The skill names behaviour.py in `python_dir` declares (SKILL_NAMES), or None where it
    declares none (a behaviour of the user's own, which reads robot.params as it likes)."""
    try:
        tree = ast.parse((python_dir / "behaviour.py").read_text())
    except (OSError, SyntaxError, ValueError):
        return None  # the robot says what is wrong with it when it plays (and reloads it when fixed)
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "SKILL_NAMES" for t in node.targets):
            try:
                return tuple(ast.literal_eval(node.value))
            except ValueError:
                return None
    return None


def check_python_skill(option: str, skill: str, python_dir: Path) -> None:
    known = python_skills(python_dir)
    if known is not None and skill not in known:
        raise BadInput(f"{option}: unknown Python skill '{skill}' (known: {', '.join(known)})")


def check_robot(bin_shim: Path, option: str, shim_argv: list) -> None:
    """One robot of a team as the match would start it (--team/--player included)."""
    run_check(bin_shim, shim_argv, option)
