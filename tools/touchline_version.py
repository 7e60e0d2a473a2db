"""Every Python tool's --version ("tools/match 0.9.0"): the VERSION file at the source root (or
its installed copy, touchline_paths.py), the one CMake's project() reads for the C++ programs too."""
from __future__ import annotations

import argparse

import touchline_paths

VERSION_FILE = touchline_paths.SHARE / "VERSION"


def version() -> str:
    return touchline_paths.version()


def add_version_option(parser: argparse.ArgumentParser, program: str) -> None:
    parser.add_argument("--version", action="version", version=f"{program} {version()}",
                        help="print the program's name and version and exit")
