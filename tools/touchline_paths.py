"""Where Touchline's files are, in the source tree or installed (`pip install .`, cmake --install),
and where a match's messages are (the ports of its LCM URL): the one place the Python tools, the
viewer and learning ask.

Reads only the file system. Two layouts:
- the source tree: this file is tools/touchline_paths.py; the programs are in build/bin
  ($TOUCHLINE_BUILD_DIR overrides build/), config/, behaviour_py/ and VERSION at the root, the
  message types' Python in build/lcm_types/gen/python.
- installed: this file is a top-level module in site-packages; the prefix above it (a venv, ~/.local,
  /usr/local, a cmake --install prefix) has the programs in bin/ and share/touchline/ with
  config/, behaviour_py/ and VERSION, the layout `cmake --install` makes (cmake/install.cmake),
  and the message types' package `touchline` is importable as it is.
"""
from __future__ import annotations

import os
from pathlib import Path

_HERE = Path(__file__).resolve().parent


def _source_root() -> Path | None:
    root = _HERE.parent
    if _HERE.name == "tools" and (root / "VERSION").is_file() and (root / "CMakeLists.txt").is_file():
        return root
    return None


def _installed_prefix() -> Path | None:
    # site-packages is lib/pythonX.Y/site-packages (or dist-packages) under the prefix.
    for prefix in list(_HERE.parents)[:4]:
        if (prefix / "share" / "touchline" / "VERSION").is_file():
            return prefix
    return None


ROOT = _source_root()
"""The source tree, or None when installed."""
PREFIX = None if ROOT else _installed_prefix()
"""The install prefix (its bin/ has the programs), or None in the source tree."""
if ROOT is None and PREFIX is None:
    raise ImportError(f"touchline_paths: neither a source tree nor an installed prefix above {_HERE}")

SHARE = ROOT if ROOT else PREFIX / "share" / "touchline"
"""The folder with config/, behaviour_py/ and VERSION."""


def build_dir() -> Path:
    """The folder whose bin/ has sim_world, robot_shim and touchline_match: the source tree's
    build/ ($TOUCHLINE_BUILD_DIR overrides it), or the install prefix."""
    if ROOT:
        return Path(os.environ.get("TOUCHLINE_BUILD_DIR", ROOT / "build"))
    return PREFIX


def config_file(name: str) -> Path:
    """A file of config/ (spl2011.ini, walk.ini, policies/...)."""
    return SHARE / "config" / name


def behaviour_py() -> Path:
    """The Python behaviour's folder (robot_shim --python-dir's default)."""
    return SHARE / "behaviour_py"


def work_dir(name: str) -> Path:
    """Where a tool writes its output by default (logs/, out/): under the source tree there, else
    under the current directory."""
    return (ROOT or Path.cwd()) / name


def lcm_python_dirs(build: Path | None = None) -> list[str]:
    """The folders to put on sys.path for the message types' package `touchline` of a build folder
    or an install prefix (none needed when installed by pip: it is in site-packages)."""
    build = build or build_dir()
    return [str(build / "lcm_types" / "gen" / "python"), str(build / "share" / "touchline" / "lcm_types" / "python")]


def version() -> str:
    """The VERSION file's version, the one every program's --version prints."""
    return (SHARE / "VERSION").read_text().strip()


def lane_urls(url: str) -> list[str]:
    """The URLs to watch a match on `url` by: for udpm://GROUP:PORT?OPTIONS also the robots' answers'
    port above it, as bridge/lcm lanes.cpp derives it (the port above that only repeats what the
    world sends on the first); any other URL is the only one."""
    if not url.startswith("udpm://"):
        return [url]
    network, _, options = url[len("udpm://"):].partition("?")
    group, colon, port = (network or "239.255.76.67:7667").partition(":")
    try:
        number = int(port, 0) if colon else 0
    except ValueError:
        return [url]
    if not 1 <= number <= 65535 - 2:
        return [url]
    return [url, f"udpm://{group}:{number + 1}" + (f"?{options}" if options else "")]
