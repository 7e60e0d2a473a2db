"""Touchline's files (config/, behaviour_py/, VERSION, the viewer's page): touchline_paths, the one
resolver of the source tree's or the installed layout. Installed (pip install .), it is a
top-level module; in the source tree it is tools/touchline_paths.py, beside this package's folder."""
import sys
from pathlib import Path

try:
    import touchline_paths
except ModuleNotFoundError:  # the source tree, run without tools/ on sys.path
    sys.path.append(str(Path(__file__).resolve().parents[2] / "tools"))
    import touchline_paths  # noqa: F401 (re-exported)
