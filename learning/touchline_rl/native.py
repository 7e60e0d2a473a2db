"""The `touchline_sim` extension, found in $TOUCHLINE_PYTHON_DIR or the default build's
build/python (tools/setup builds it there), or installed beside this package (pip install .)."""
import os
import pathlib
import sys

from touchline_rl.home import touchline_paths

REPO = pathlib.Path(__file__).resolve().parents[2]


def _import():
    if "TOUCHLINE_PYTHON_DIR" not in os.environ and touchline_paths.ROOT is None:  # installed
        import touchline_sim
        return touchline_sim
    where = os.environ.get("TOUCHLINE_PYTHON_DIR", str(REPO / "build" / "python"))
    if where not in sys.path:
        sys.path.insert(0, where)
    try:
        import touchline_sim
    except ImportError as error:
        raise ImportError(f"touchline_sim extension not found in {where} (build with tools/setup, "
                          f"or set TOUCHLINE_PYTHON_DIR): {error}") from None
    return touchline_sim


touchline_sim = _import()
