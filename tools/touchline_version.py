"""Every Python tool's --version ("tools/match 0.9.0"): the VERSION file at the source root,
the one CMake's project() reads for the C++ programs too."""
from __future__ import annotations

import argparse
from pathlib import Path

VERSION_FILE = Path(__file__).resolve().parents[1] / "VERSION"


def version() -> str:
    return VERSION_FILE.read_text().strip()


def add_version_option(parser: argparse.ArgumentParser, program: str) -> None:
    parser.add_argument("--version", action="version", version=f"{program} {version()}",
                        help="print the program's name and version and exit")
