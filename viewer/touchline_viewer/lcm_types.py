"""Imports Touchline's generated Python LCM types (package `touchline`).

PYTHONPATH normally carries <build>/lcm_types/gen/python; when it does not, the build named
by TOUCHLINE_BUILD_DIR, or else the repository's build/, is tried."""
import os
import sys
from pathlib import Path

from .errors import ViewerError

REPO = Path(__file__).resolve().parents[2]


def import_touchline():
    try:
        import touchline
        return touchline
    except ImportError:
        pass
    build = Path(os.environ.get("TOUCHLINE_BUILD_DIR", REPO / "build"))
    gen = build / "lcm_types" / "gen" / "python"
    if (gen / "touchline").is_dir():
        sys.path.append(str(gen))
        import touchline
        return touchline
    raise ViewerError(f"cannot import the LCM types (package touchline): build first (tools/setup) "
                      f"or set PYTHONPATH=<build>/lcm_types/gen/python (looked in {gen})")
