"""A sweep's outputs from its rows (sweep_play.COLUMNS): the tidy table (matches.csv, a row
per match), a summary per grid cell with 95 % confidence intervals (summary.csv and
summary.json) and a plot of it (summary.png). Writes only into the folder it is given.

Intervals are Student-t intervals of the mean over a cell's played matches (status ok or
shim_died): mean +- t(0.975, n-1) * s / sqrt(n); with fewer than 2 matches there is none.
"""
from __future__ import annotations

import csv
import json
import math
import statistics
from pathlib import Path

from scipy import stats

from sweep_play import COLUMNS

PLAYED = ("ok", "shim_died")  # statuses whose match has a score
MEASURES = ["goals0", "goals1", "goal_difference", "penalties0", "penalties1", "possession0", "stuck_s0", "stuck_s1",
            "ball_moving_share", "rtf"]


def ci95(values: list[float]) -> tuple[float, float] | None:
    """The 95 % t-interval of the mean of `values`; None for fewer than 2."""
    n = len(values)
    if n < 2:
        return None
    mean = statistics.fmean(values)
    half = stats.t.ppf(0.975, n - 1) * statistics.stdev(values) / math.sqrt(n)
    return (mean - half, mean + half)


def summarise(rows: list[dict]) -> list[dict]:
    """One entry per grid cell, in cell order: its settings, how many matches played and
    failed, wins/draws/losses of team 0, and each measure's mean and 95 % interval."""
    cells: dict[int, list[dict]] = {}
    for row in rows:
        cells.setdefault(row["cell"], []).append(row)
    summary = []
    for cell, members in sorted(cells.items()):
        played = [r for r in members if r["status"] in PLAYED]
        first = members[0]
        entry = {"cell": cell, "label": first["label"], "team0": first["team0"], "team1": first["team1"],
                 "settings": first["settings"], "variant": first["variant"], "matches": len(played),
                 "failed": len(members) - len(played), "shim_died": sum(r["status"] == "shim_died" for r in played),
                 "wins0": sum(r["goal_difference"] > 0 for r in played),
                 "draws": sum(r["goal_difference"] == 0 for r in played),
                 "losses0": sum(r["goal_difference"] < 0 for r in played)}
        for measure in MEASURES:
            values = [float(r[measure]) for r in played if r[measure] != ""]
            interval = ci95(values)
            entry[f"{measure}_mean"] = statistics.fmean(values) if values else None
            entry[f"{measure}_ci95"] = list(interval) if interval else None
        summary.append(entry)
    return summary


def write(out: Path, rows: list[dict], summary: list[dict]) -> None:
    """matches.csv, summary.csv, summary.json and summary.png into `out`."""
    out.mkdir(parents=True, exist_ok=True)
    rows = sorted(rows, key=lambda r: (r["cell"], r["seed"]))
    with open(out / "matches.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    flat = []  # the CSV has an interval as two columns, _lo and _hi
    for entry in summary:
        row = {}
        for key, value in entry.items():
            if key.endswith("_ci95"):
                row[f"{key}_lo"], row[f"{key}_hi"] = value if value else ("", "")
            else:
                row[key] = "" if value is None else value
        flat.append(row)
    with open(out / "summary.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(flat[0]) if flat else ["cell"])
        writer.writeheader()
        writer.writerows(flat)
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    plot(out / "summary.png", summary)


def plot(path: Path, summary: list[dict]) -> None:
    """Goals for and against team 0 and the goal difference per cell, means with their 95 %
    intervals as error bars (matplotlib, no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = [e["label"] for e in summary]
    ys = range(len(summary))
    figure, axes = plt.subplots(1, 2, figsize=(12, 1.5 + 0.5 * len(summary)), sharey=True, squeeze=False)
    panels = [("goals per match", [("goals0", "team 0"), ("goals1", "team 1")]),
              ("goal difference (team 0 - team 1)", [("goal_difference", "difference")])]
    for axis, (title, measures) in zip(axes[0], panels):
        for offset, (measure, name) in zip((-0.15, 0.15) if len(measures) == 2 else (0,), measures):
            means = [e[f"{measure}_mean"] if e[f"{measure}_mean"] is not None else math.nan for e in summary]
            errors = [[m - e[f"{measure}_ci95"][0] if e[f"{measure}_ci95"] else 0 for m, e in zip(means, summary)],
                      [e[f"{measure}_ci95"][1] - m if e[f"{measure}_ci95"] else 0 for m, e in zip(means, summary)]]
            axis.errorbar(means, [y + offset for y in ys], xerr=errors, fmt="o", capsize=4, label=name)
        axis.set_title(title)
        axis.grid(alpha=0.3)
        axis.legend(loc="best")
    axes[0][1].axvline(0, color="grey", linewidth=1)
    axes[0][0].set_yticks(list(ys), labels)
    axes[0][0].invert_yaxis()
    figure.suptitle("sweep: means and 95 % confidence intervals")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)
