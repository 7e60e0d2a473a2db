"""A sweep's grid: which matches to play. Reads the command line's (or a TOML grid file's)
teams, world config overrides, launcher variants and seeds; writes nothing. Each grid cell
is one combination of settings; each cell is played once per seed.

  team0 / team1  behaviour specs as tools/match takes them (py:Team, cpp:Team,walker=learned);
                 several in one argument are split where a new LANG: starts, so
                 "py:Striker,cpp:Team,walker=learned" is two specs
  set            SECTION.KEY=V1,V2,...: world config overrides, every value a cell
  variant        a string of launcher options (shell words), every variant a cell,
                 e.g. "--walk-engine nao-joints" or "--in-process"
  launch         launcher options every match gets (e.g. --duration 10 --team-size 2)
  seeds          1-20, 1,3,5 or 1-5,10
"""
from __future__ import annotations

import itertools
import re
import shlex
import tomllib
from pathlib import Path

SPEC_START = re.compile(r"^(py|cpp|runswift):")


class GridError(ValueError):
    """A grid that cannot be played: its message is the one line the user sees."""


def split_specs(text: str) -> list[str]:
    """'py:Striker,cpp:Team,walker=learned' -> ['py:Striker', 'cpp:Team,walker=learned']:
    a comma followed by LANG: starts a new spec; any other comma separates a parameter."""
    specs: list[str] = []
    for piece in text.split(","):
        if SPEC_START.match(piece) or not specs:
            specs.append(piece)
        else:
            specs[-1] += "," + piece
    bad = [s for s in specs if not SPEC_START.match(s)]
    if bad or not text:
        raise GridError(f"a team must be py:SKILL, cpp:SKILL or runswift:SKILL (got '{text}')")
    return specs


def parse_seeds(text: str) -> list[int]:
    """'1-3,7' -> [1, 2, 3, 7], in the order given, without repeats."""
    seeds: list[int] = []
    for part in str(text).split(","):
        first, dash, last = part.strip().partition("-")
        try:
            lo = int(first)
            hi = int(last) if dash else lo
        except ValueError:
            raise GridError(f"seeds must be like 1-20, 1,3,5 or 1-5,10 (got '{text}')") from None
        if hi < lo:
            raise GridError(f"seed range {part.strip()} runs backwards")
        seeds += [s for s in range(lo, hi + 1) if s not in seeds]
    return seeds


def parse_set(text: str) -> tuple[str, list[str]]:
    """'rules.half_s=300,600' -> ('rules.half_s', ['300', '600'])."""
    key, eq, values = text.partition("=")
    if not eq or "." not in key or not values or any(not v for v in values.split(",")):
        raise GridError(f"--set must be SECTION.KEY=VALUE[,VALUE...] (got '{text}')")
    return key, values.split(",")


def expand(team0: list[str], team1: list[str], sets: dict[str, list[str]], variants: list[str],
           seeds: list[int], launch: list[str]) -> list[dict]:
    """Every match of the grid, cell by cell, seed by seed. An empty team list leaves that team
    to the launcher's default; an empty variant list is one variant with no options. Each match
    is a plain dict (it travels to worker processes and Ray tasks)."""
    if not seeds:
        raise GridError("no seeds: give --seeds (e.g. 1-20)")
    keys = list(sets)
    cells = itertools.product(team0 or [None], team1 or [None], itertools.product(*(sets[k] for k in keys)),
                              variants or [""])
    matches = []
    for cell, (t0, t1, values, variant) in enumerate(cells):
        settings = [f"{k}={v}" for k, v in zip(keys, values)]
        try:
            variant_args = shlex.split(variant)
        except ValueError as e:
            raise GridError(f"variant '{variant}': {e}") from None
        for seed in seeds:
            matches.append({"cell": cell, "team0": t0, "team1": t1, "settings": settings, "variant": variant,
                            "seed": seed, "launch": [*launch, *variant_args]})
    return matches


def launcher_args(match: dict) -> list[str]:
    """The launcher's options for one match (besides where its outputs go)."""
    teams = [arg for team in (0, 1) if match[f"team{team}"] for arg in (f"--team{team}", match[f"team{team}"])]
    return [*teams, *(arg for s in match["settings"] for arg in ("--set", s)), "--seed", str(match["seed"]),
            *match["launch"]]


def cell_label(match: dict) -> str:
    """A cell's name in tables and plots: 'py:Team v cpp:Team rules.half_s=300 [--in-process]'."""
    parts = [f"{match['team0'] or 'default'} v {match['team1'] or 'default'}", *match["settings"]]
    if match["variant"]:
        parts.append(f"[{match['variant']}]")
    return " ".join(parts)


def from_file(path: Path) -> dict:
    """A TOML grid file's team0, team1, set, variants, seeds and launch, checked:

        seeds = "1-20"
        team0 = ["py:Team"]
        team1 = ["py:Striker", "cpp:Team"]
        variants = ["", "--walk-engine nao-joints"]
        launch = ["--duration", "60", "--team-size", "3"]
        [set]
        "rules.half_s" = [300, 600]
    """
    try:
        data = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise GridError(f"grid file {path}: {e}") from None
    known = {"team0", "team1", "set", "variants", "seeds", "launch"}
    if unknown := sorted(set(data) - known):
        raise GridError(f"grid file {path}: unknown key(s) {', '.join(unknown)} (known: {', '.join(sorted(known))})")

    def strings(key: str) -> list[str]:
        value = data.get(key, [])
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise GridError(f"grid file {path}: {key} must be a list of strings")
        return value

    sets = data.get("set", {})
    if not isinstance(sets, dict) or not all(isinstance(v, list) and v for v in sets.values()):
        raise GridError(f"grid file {path}: [set] must give each SECTION.KEY a non-empty list of values")
    return {"team0": [s for t in strings("team0") for s in split_specs(t)],
            "team1": [s for t in strings("team1") for s in split_specs(t)],
            "set": {k: [str(v).lower() if isinstance(v, bool) else str(v) for v in vs] for k, vs in sets.items()},
            "variants": strings("variants"), "launch": strings("launch"),
            "seeds": parse_seeds(data["seeds"]) if "seeds" in data else []}
