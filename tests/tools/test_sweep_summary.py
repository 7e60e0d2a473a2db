"""A sweep's summary: per grid cell, played matches only, t-intervals, and its files."""
import csv
import json
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import sweep_summary  # noqa: E402
from sweep_play import COLUMNS  # noqa: E402


def row(cell, seed, goals0, goals1, status="ok"):
    r = {c: "" for c in COLUMNS}
    r.update(cell=cell, label=f"cell {cell}", seed=seed, status=status)
    if status != "failed":
        r.update(goals0=goals0, goals1=goals1, goal_difference=goals0 - goals1, rtf=2.0, possession0=0.5)
    else:
        r["error"] = "launch: stopping the match: sim_world exited with 1"
    return r


def test_t_interval_of_the_mean():
    lo, hi = sweep_summary.ci95([1, 2, 3, 4, 5])  # mean 3, s = 1.581, t(0.975, 4) = 2.776
    assert lo == pytest.approx(3 - 1.963, abs=1e-3) and hi == pytest.approx(3 + 1.963, abs=1e-3)
    assert sweep_summary.ci95([2, 2, 2]) == (2, 2)
    assert sweep_summary.ci95([4]) is None


def test_a_cell_summarises_its_played_matches_and_counts_the_failed():
    rows = [row(0, 1, 2, 0), row(0, 2, 1, 1), row(0, 3, 0, 3, status="shim_died"), row(0, 4, 0, 0, status="failed"),
            row(1, 1, 5, 0)]
    first, second = sweep_summary.summarise(rows)
    assert (first["matches"], first["failed"], first["shim_died"]) == (3, 1, 1)
    assert (first["wins0"], first["draws"], first["losses0"]) == (1, 1, 1)
    assert first["goals0_mean"] == pytest.approx(1.0)
    assert first["goal_difference_mean"] == pytest.approx(-1 / 3)
    assert first["goal_difference_ci95"][0] < -1 / 3 < first["goal_difference_ci95"][1]
    assert first["stuck_s0_mean"] is None  # no log, no figure: never a made-up zero
    assert second["matches"] == 1 and second["goals0_ci95"] is None


def test_outputs(tmp_path):
    rows = [row(0, 2, 1, 0), row(0, 1, 2, 0), row(1, 1, 0, 0, status="failed")]
    sweep_summary.write(tmp_path, rows, sweep_summary.summarise(rows))
    with open(tmp_path / "matches.csv") as f:
        table = list(csv.DictReader(f))
    assert [(r["cell"], r["seed"]) for r in table] == [("0", "1"), ("0", "2"), ("1", "1")]
    assert list(table[0]) == COLUMNS
    assert table[2]["status"] == "failed" and "sim_world" in table[2]["error"] and table[2]["goals0"] == ""
    with open(tmp_path / "summary.csv") as f:
        summary = list(csv.DictReader(f))
    assert float(summary[0]["goals0_ci95_lo"]) < 1.5 < float(summary[0]["goals0_ci95_hi"])
    assert summary[1]["matches"] == "0" and summary[1]["failed"] == "1" and summary[1]["goals0_mean"] == ""
    assert json.loads((tmp_path / "summary.json").read_text())[0]["goals0_mean"] == 1.5
    assert (tmp_path / "summary.png").read_bytes()[:4] == b"\x89PNG"
