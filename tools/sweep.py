#!/usr/bin/env python3
"""Plays seeded matches over a grid of settings, side by side on every local core (or as Ray
tasks on a cluster, --ray), and writes one tidy table (matches.csv, a row per match: goals,
penalties, falls, possession, stuck time, real-time factor, truth hash) and a summary per
grid cell with 95 % confidence intervals (summary.csv, summary.json, summary.png).

  tools/sweep --team0 py:Team --team1 py:Striker,cpp:Team --set rules.half_s=300 --seeds 1-20 \\
              -- --team-size 3 --duration 120

Options after `--` go to every match's launcher (tools/match --help); --variant gives a grid
axis of launcher options. A grid may also come from a TOML file (--grid, see sweep_grid.py).
Each match runs in a private network namespace of its own, so matches never share a bus. A
failed match is a row with its error; Ctrl-C or SIGTERM stops every match and writes what
finished.
"""
from __future__ import annotations

import argparse
import concurrent.futures
import contextlib
import datetime
import io
import os
import signal
import sys
import threading
from pathlib import Path

import sweep_grid
import sweep_summary
from sweep_grid import GridError, cell_label
import touchline_paths
from sweep_play import COLUMNS, play
from touchline_version import add_version_option

HERE = Path(__file__).resolve().parent  # tools/, or the installed touchline_tools/
EXIT_FAILED_MATCHES, EXIT_BAD_GRID = 1, 2
CORES = len(os.sched_getaffinity(0))  # the cores this process may run on (a container's, not the host's)


def parse_args(argv: list[str]) -> tuple[argparse.Namespace, list[dict]]:
    """The options and the grid's matches; one line and exit 2 on a grid that cannot be played."""
    own, launch = (argv[:argv.index("--")], argv[argv.index("--") + 1:]) if "--" in argv else (argv, [])
    p = argparse.ArgumentParser(prog="tools/sweep", description=__doc__.split("\n\n")[0],
                                usage="%(prog)s [options] [-- LAUNCHER OPTIONS...]")
    add_version_option(p, "tools/sweep")
    p.add_argument("--grid", type=Path, help="a TOML grid file (its settings join the command line's)")
    p.add_argument("--team0", action="append", default=[], metavar="SPECS",
                   help="team 0's behaviours, a grid axis: py:Team or several, py:Team,cpp:Team (repeatable)")
    p.add_argument("--team1", action="append", default=[], metavar="SPECS", help="team 1's behaviours, likewise")
    p.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=V1[,V2...]",
                   help="a world config value, every value a grid axis point (repeatable)")
    p.add_argument("--variant", action="append", default=[], metavar="'LAUNCHER OPTIONS'",
                   help="launcher options as one string, every --variant a grid axis point; one that starts with "
                        "a dash and has no space needs =, e.g. --variant=--in-process")
    p.add_argument("--seeds", help="the seeds every grid cell plays: 1-20, 1,3,5 or 1-5,10 (default 1)")
    p.add_argument("--workers", type=int, default=CORES,
                   help=f"matches at once (default: every core, {CORES} here); with --ray local, "
                        "the local Ray instance's CPUs")
    p.add_argument("--ray", metavar="ADDRESS",
                   help="play every match as a Ray task: HOST:PORT of a cluster's head, 'auto' (the cluster "
                        "this machine is part of) or 'local' (start a Ray instance here)")
    p.add_argument("--cpus-per-match", type=float, default=1.0, help="Ray CPUs each match reserves (default 1)")
    p.add_argument("--out", type=Path, help="output folder (default out/sweep-DATE_TIME)")
    p.add_argument("--keep-logs", action="store_true", help="keep each match's LCM log in OUT/logs (with --ray: "
                   "on the machine that played it)")
    p.add_argument("--build-dir", type=Path, default=touchline_paths.build_dir())
    p.add_argument("--no-progress", action="store_true", help="no progress bar: a line per match")
    args = p.parse_args(own)
    if args.workers < 1:
        p.error("--workers must be at least 1")
    if args.cpus_per_match <= 0:
        p.error("--cpus-per-match must be > 0")
    try:
        grid = sweep_grid.from_file(args.grid) if args.grid else {"team0": [], "team1": [], "set": {},
                                                                  "variants": [], "launch": [], "seeds": []}
        team0 = grid["team0"] + [s for t in args.team0 for s in sweep_grid.split_specs(t)]
        team1 = grid["team1"] + [s for t in args.team1 for s in sweep_grid.split_specs(t)]
        sets = dict(grid["set"])
        for item in args.set:
            key, values = sweep_grid.parse_set(item)
            sets[key] = values
        seeds = sweep_grid.parse_seeds(args.seeds) if args.seeds else grid["seeds"] or [1]
        matches = sweep_grid.expand(team0, team1, sets, grid["variants"] + args.variant, seeds,
                                    grid["launch"] + launch)
        check_launcher_options(matches)
    except GridError as e:
        p.exit(EXIT_BAD_GRID, f"sweep: {e}\n")
    if args.out is None:
        args.out = touchline_paths.work_dir("out") / f"sweep-{datetime.datetime.now():%Y-%m-%d_%H%M%S}"
    return args, matches


def check_launcher_options(matches: list[dict]) -> None:
    """Every cell's launcher options as the launcher itself reads them: a typo is one line
    now, not a failed row for every match."""
    import launch
    seen = set()
    for match in matches:
        if match["cell"] in seen:
            continue
        seen.add(match["cell"])
        errors = io.StringIO()
        try:
            with contextlib.redirect_stderr(errors):
                launch.parse_args(sweep_grid.launcher_args(match))
        except SystemExit:
            why = (errors.getvalue().strip().splitlines() or ["bad options"])[-1].split("error: ", 1)[-1]
            raise GridError(f"cell {cell_label(match)}: the launcher refuses its options: {why}") from None


class Progress:
    """A rich progress bar on a terminal; otherwise (or with --no-progress) a line per match."""

    def __init__(self, total: int, bar: bool):
        self.total, self.done = total, 0
        self.bar = None
        if bar:
            from rich.progress import BarColumn, MofNCompleteColumn, Progress as Bar, TimeElapsedColumn, \
                TimeRemainingColumn
            self.bar = Bar("sweep", BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TimeRemainingColumn(),
                           transient=False)
            self.task = self.bar.add_task("matches", total=total)
            self.bar.start()

    def add(self, row: dict) -> None:
        self.done += 1
        if row["status"] in sweep_summary.PLAYED:
            what = f"{row['goals0']}:{row['goals1']} (x{row['rtf']:.1f} real time)"
        else:
            what = f"failed: {row['error']}"
        line = f"sweep: {self.done}/{self.total} {row['label']} seed {row['seed']}: {what}"
        if self.bar:
            self.bar.console.print(line, highlight=False, markup=False)
            self.bar.advance(self.task)
        else:
            print(line, flush=True)

    def close(self) -> None:
        if self.bar:
            self.bar.stop()


def run_local(matches: list[dict], workers: int, build_dir: Path, keep_logs: Path | None, on_row) -> list[dict]:
    """Plays the matches, `workers` at once, each as its launcher process (threads only wait
    for them); calls on_row(row) as each ends. On KeyboardInterrupt stops every running
    match, then re-raises with the rows so far on the exception (`rows`)."""
    stop = threading.Event()
    rows: list[dict] = []
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=workers)
    futures = {pool.submit(play, m, build_dir, keep_logs, stop): m for m in matches}

    def row_of(future) -> dict:
        try:
            return future.result()
        except Exception as e:  # noqa: BLE001 - a match that could not even start is a failed row, named
            return failed_row(futures[future], f"{type(e).__name__}: {e}")

    gathered = set()
    try:
        for future in concurrent.futures.as_completed(futures):
            gathered.add(future)
            rows.append(row_of(future))
            on_row(rows[-1])
    except KeyboardInterrupt as interrupt:
        stop.set()  # every running match stops its launcher; the ones not started never start
        pool.shutdown(wait=True, cancel_futures=True)
        rows += [row_of(f) for f in futures if f not in gathered and f.done() and not f.cancelled()]
        interrupt.rows = rows
        raise
    pool.shutdown()
    return rows


def run_ray(matches: list[dict], address: str, workers: int, cpus_per_match: float, build_dir: Path,
            keep_logs: Path | None, on_row) -> list[dict]:
    """Plays each match as one Ray task (sweep_play.play in a Ray worker, which runs the
    launcher in a network namespace of its own); gathers the rows as tasks end. Every machine
    of the cluster needs this tree, built, at the same path. KeyboardInterrupt cancels every
    task (a cancelled task stops its launcher) and re-raises as run_local does."""
    import ray
    # Ray workers import sweep_play (and what it imports) from this folder (tools/ or the installed package's).
    paths = [str(HERE), *touchline_paths.lcm_python_dirs(build_dir), os.environ.get("PYTHONPATH", "")]
    runtime_env = {"env_vars": {"PYTHONPATH": os.pathsep.join(p for p in paths if p)}}
    options = {"runtime_env": runtime_env, "log_to_driver": False, "configure_logging": False}
    if address == "local":
        ray.init(num_cpus=workers, include_dashboard=False, **options)
    else:
        ray.init(address=address, **options)
    rows: list[dict] = []
    try:
        task = ray.remote(num_cpus=cpus_per_match, max_retries=0)(play)
        pending = {task.remote(m, build_dir, keep_logs): m for m in matches}
        try:
            while pending:
                done, _ = ray.wait(list(pending), num_returns=1)
                for ref in done:
                    match = pending.pop(ref)
                    try:
                        row = ray.get(ref)
                    except Exception as e:  # noqa: BLE001 - a task that died is a failed row, named
                        row = failed_row(match, f"Ray task failed: {str(e).strip().splitlines()[0]}")
                    rows.append(row)
                    on_row(row)
        except KeyboardInterrupt as interrupt:
            for ref in pending:
                ray.cancel(ref)
            ray.wait(list(pending), num_returns=len(pending), timeout=60)
            interrupt.rows = rows
            raise
    finally:
        ray.shutdown()
    return rows


def failed_row(match: dict, error: str) -> dict:
    row = {c: "" for c in COLUMNS}
    row.update(cell=match["cell"], label=cell_label(match), team0=match["team0"] or "", team1=match["team1"] or "",
               settings=" ".join(match["settings"]), variant=match["variant"], seed=match["seed"], status="failed",
               error=error)
    return row


def sweep(matches: list[dict], workers: int, build_dir: Path, out: Path, ray: str | None = None,
          cpus_per_match: float = 1.0, keep_logs: bool = False, progress: bool = False) -> list[dict]:
    """Plays every match and writes the tables and plot to `out`; the rows. A KeyboardInterrupt
    writes what finished first, then goes on up."""
    bar = Progress(len(matches), progress)
    logs = out / "logs" if keep_logs else None
    try:
        if ray:
            rows = run_ray(matches, ray, workers, cpus_per_match, build_dir, logs, bar.add)
        else:
            rows = run_local(matches, workers, build_dir, logs, bar.add)
    except KeyboardInterrupt as interrupt:
        bar.close()
        rows = getattr(interrupt, "rows", [])
        sweep_summary.write(out, rows, sweep_summary.summarise(rows))
        raise
    bar.close()
    sweep_summary.write(out, rows, sweep_summary.summarise(rows))
    return rows


def report(summary: list[dict]) -> None:
    """A line per grid cell: goals, goal difference with its 95 % interval, results."""
    def with_ci(entry, measure, sign=""):
        mean, ci = entry[f"{measure}_mean"], entry[f"{measure}_ci95"]
        if mean is None:
            return "-"
        return f"{mean:{sign}.2f}" + (f" [{ci[0]:{sign}.2f}, {ci[1]:{sign}.2f}]" if ci else "")

    for e in summary:
        print(f"cell {e['cell']} {e['label']}: {e['matches']} matches ({e['failed']} failed); goals "
              f"{with_ci(e, 'goals0')} : {with_ci(e, 'goals1')}; difference {with_ci(e, 'goal_difference', '+')}; "
              f"team 0 won {e['wins0']}, drew {e['draws']}, lost {e['losses0']}")


def main(argv: list[str]) -> int:
    def terminate(signum, _frame):
        raise KeyboardInterrupt  # SIGTERM stops the sweep as Ctrl-C does

    signal.signal(signal.SIGTERM, terminate)
    signal.signal(signal.SIGINT, signal.default_int_handler)  # even where started with SIGINT ignored (a & job)
    args, matches = parse_args(argv)
    where = f"on Ray ({args.ray})" if args.ray else f"{min(args.workers, len(matches))} at a time"
    print(f"sweep: {len(matches)} matches in {len({m['cell'] for m in matches})} grid cells, {where}; "
          f"results in {args.out}", flush=True)
    try:
        rows = sweep(matches, args.workers, args.build_dir, args.out, args.ray, args.cpus_per_match,
                     args.keep_logs, sys.stderr.isatty() and not args.no_progress)
    except KeyboardInterrupt:
        print(f"sweep: interrupted; the matches that finished are in {args.out}", file=sys.stderr)
        return 130
    report(sweep_summary.summarise(rows))
    failed = sum(r["status"] not in sweep_summary.PLAYED for r in rows)
    if failed:
        print(f"sweep: {failed} of {len(rows)} matches failed (their errors are in {args.out / 'matches.csv'})",
              file=sys.stderr)
        return EXIT_FAILED_MATCHES
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
