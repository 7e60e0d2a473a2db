#!/usr/bin/env python3
"""Plays a headless Touchline match: starts sim_world and one robot_shim per robot, waits
for them, shuts everything down cleanly on Ctrl-C or SIGTERM or when the world fails (naming
which process and why), and prints what happened. A robot_shim that dies during the match
is restarted or not (--restart-dead) and the match goes on (shim_keeper.py).

Every match is recorded to an LCM event log (lcm-logger format) named by date and seed.
By default every robot runs the Python behaviour (behaviour_py) as a team: a goalie, and
the striker, defender and midfielder chosen through team communication (thesis ch. 4).
"""
from __future__ import annotations

import argparse
import datetime
import json
import logging
import os
import secrets
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import types
from pathlib import Path

from match_checks import BadInput, check_python_skill, check_robot, check_world
from match_processes import SECRET_ENV, Children
from match_watch import MatchWatch
from shim_keeper import ShimKeeper
import touchline_paths
from touchline_version import add_version_option

# The programs, config/ and behaviour_py/: the source tree's or the installed ones (touchline_paths.py).
DEFAULT_BUILD = touchline_paths.build_dir()
SHIMS_EXIT_S = 10  # wall seconds the shims may take to exit once the world has ended the match
MATCH_CONFIG_WAIT_S = 10  # wall seconds sim_world may take to publish the match (TL_MATCH) once started

# Exit codes besides 0 (a clean match) and 2 (bad options): the match stopped (a process or
# the watcher failed), a robot_shim died (the match played to its end all the same), or a
# signal stopped the launcher (128 + the signal).
EXIT_FAILED, EXIT_SHIM_DIED = 1, 3

# The walk engines robot_shim --walk-engine knows (robot::walk_engine_names(); the shim
# checks the name again: runswift only in a build with -DTOUCHLINE_RUNSWIFT_DIR), the
# default first.
WALK_ENGINES = ("walkcycle", "nao-joints", "runswift")

# Kick-off positions (field frame, team 0 defending -x) as fractions of the half length
# and half width, and a heading: goalie, defender, two forwards, then more supporters.
FORMATION = [(-0.9, 0.0, 0.0), (-0.6, 0.0, 0.0), (-0.3, 0.4, 0.0), (-0.3, -0.4, 0.0),
             (-0.45, 0.7, 0.0), (-0.45, -0.7, 0.0), (-0.15, 0.0, 0.0)]

# robot_shim's options a user may want in a match, passed to every shim as given (option,
# argparse keywords). The launcher sets --team, --player, --behaviour, --param, --walk-config,
# --walk-engine, --field-config, --lcm-url and --data-dir itself (above); --secret-file,
# --join-timeout and --world-timeout are for shims started by hand
# (tests/tools/test_launch.py holds the launcher to robot_shim --help with this list).
SHIM_OPTIONS = [
    ("--python-dir", dict(type=Path, help="the Python behaviour's folder for py teams (default: robot_shim's, "
                                          "behaviour_py/)")),
    ("--kick-config", dict(type=Path, help="kick and dribble parameters file (default: the built-in kick)")),
    ("--head-config", dict(type=Path, help="head joint limits and speed file (default: the built-in head)")),
    ("--charge-cpu", dict(action="store_true", help="charge each behaviour tick's CPU time to simulated time")),
    ("--perfect-localisation", dict(action="store_true", help="every robot's pose from the truth")),
    ("--tick-timeout-ms", dict(type=int, help="wall time a Python tick() may run before it is interrupted "
                                               "(robot_shim's default: 10000; 0: never)")),
    ("--snapshot-every", dict(type=int, help="publish each robot's Blackboard on TL_BLACKBOARD_<team>_<player> every "
                                              "N ticks (robot_shim's default: 30; 0: never)")),
    ("--runswift-config", dict(type=Path, help="--walk-engine runswift: one of their option files (their walk keys)")),
]
LOG_LEVELS = ("debug", "info", "warning", "error")
logger = logging.getLogger("launch")


def parse_args(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="tools/match", description=__doc__.split("\n\n")[0])
    add_version_option(p, "tools/match")
    p.add_argument("--team-size", type=int, default=4, help="robots per team, 1..7 (default 4)")
    p.add_argument("--duration", type=float, help="stop after this many simulated seconds "
                   "(default: the referee ends the match after two halves)")
    p.add_argument("--behaviour", choices=["py", "goto"], default="py",
                   help="py: every robot runs the Python behaviour (behaviour_py) with --skill; "
                        "goto: the C++ goto behaviour walks each robot to its kick-off spot")
    p.add_argument("--skill", default="Team", help="the Python behaviour's skill (default Team: goalie, defender, "
                   "midfielder and striker by team communication)")
    for team in (0, 1):
        p.add_argument(f"--team{team}", metavar="LANG:SKILL[,KEY=VALUE...]",
                       help=f"team {team}'s behaviour, e.g. py:Team, cpp:Team, py:Striker, with the skill's "
                            "parameters after commas, e.g. cpp:Team,walker=learned; runswift:SKILL (e.g. "
                            "runswift:WalkToPoint,headskill=HeadFindBall) runs a rUNSWift behaviour folder "
                            "(--runswift-dir); plugin:PATH:NAME the behaviour NAME of a team's own C++ library PATH "
                            "(robot_shim --behaviour-plugin) (default: --behaviour/--skill)")
    p.add_argument("--walk-engine", choices=WALK_ENGINES, default=WALK_ENGINES[0],
                   help="every robot's walk engine: walkcycle (our WalkCycle, the default), nao-joints (the same "
                        "plan as a Nao's joint angles, through our kinematics) or runswift (rUNSWift's own walk, in a "
                        "build with -DTOUCHLINE_RUNSWIFT_DIR)")
    for team in (0, 1):
        p.add_argument(f"--walk-engine{team}", choices=WALK_ENGINES, metavar="ENGINE",
                       help=f"team {team}'s walk engine, one of {', '.join(WALK_ENGINES)} (default: --walk-engine)")
    p.add_argument("--config", type=Path, default=touchline_paths.config_file("spl2011.ini"), help="world config")
    p.add_argument("--walk-config", type=Path, default=touchline_paths.config_file("walk.ini"), help="walk config")
    p.add_argument("--data-dir", type=Path, help="the robots' data directory (learned policies; default: "
                   "robot_shim's, the source tree's config/)")
    p.add_argument("--mode", choices=["lockstep", "realtime", "free"], default="lockstep")
    p.add_argument("--in-process", action="store_true",
                   help="play the world and every robot in one process (build/bin/touchline_match), as fast as "
                        "one core allows: the same match as lockstep (same seed, same truth hash) without LCM, "
                        "so no network namespace, bus, log or progress bar")
    p.add_argument("--speed", type=float, default=1.0, help="real-time multiple for realtime/free")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--robot-timeout-ms", type=int, help="wall time a robot may take to answer a frame before "
                   "the world marks it inactive (sim_world's default: 1000), unless its shim still runs")
    p.add_argument("--live-robot-timeout-ms", type=int, help="wall time a robot whose shim still runs (a busy "
                   "machine, a debugger's breakpoint) may take, so that load does not change the match "
                   "(sim_world's default: 60000)")
    p.add_argument("--restart-dead", action="store_true",
                   help="restart a robot_shim that dies during the match, once the world has marked its robot "
                        "inactive (default: the match goes on without it); not in free mode")
    p.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                   help="override a world config value (repeatable), e.g. rules.half_s=300")
    p.add_argument("--build-dir", type=Path, default=DEFAULT_BUILD,
                   help="the build folder whose bin/ has the programs, or an install prefix (cmake --install)")
    p.add_argument("--lcm-url", default="udpm://239.255.76.67:7667?ttl=0")
    p.add_argument("--runswift-dir", type=Path,
                   help="the rUNSWift behaviours folder runswift:SKILL teams run (e.g. a clone's "
                        "image/home/nao/data/behaviours)")
    p.add_argument("--host-network", action="store_true",
                   help="use this machine's network instead of a private namespace (to watch in lcm-spy)")
    p.add_argument("--json", type=Path, help="also write the match summary here as JSON")
    p.add_argument("--log-dir", type=Path, default=touchline_paths.work_dir("logs"),
                   help="where match logs go (default logs/: the source tree's, or the current directory's "
                        "when installed)")
    p.add_argument("--no-log", action="store_true", help="do not record an LCM event log")
    p.add_argument("--no-progress", action="store_true", help="no progress bar (it shows only on a terminal) "
                   "and no progress lines (every 10 %% of the match, when not on a terminal)")
    p.add_argument("--quiet", action="store_true", help="print only warnings, errors and the summary: no progress, "
                   "no launcher lines (--log-level warning --no-progress)")
    p.add_argument("--log-level", choices=LOG_LEVELS, default="info",
                   help="the launcher's and its programs' lines: debug adds each program's command line, warning "
                        "keeps only what went wrong (default info)")
    for option, keywords in SHIM_OPTIONS:
        p.add_argument(option, **keywords)
    args = p.parse_args(argv)
    if args.quiet:
        args.no_progress, args.log_level = True, "warning"
    if not 1 <= args.team_size <= 7:
        p.error("--team-size must be 1..7")
    for team in (0, 1):
        spec = getattr(args, f"team{team}")
        if spec is not None and team_behaviour(spec, args.runswift_dir or Path(".")) is None:
            p.error(f"--team{team} must be py:SKILL, cpp:SKILL, runswift:SKILL or plugin:PATH:NAME, then any "
                    f",KEY=VALUE (got '{spec}')")
        if spec is not None and spec.startswith("runswift:") and args.runswift_dir is None:
            p.error(f"--team{team} {spec} needs --runswift-dir (a rUNSWift behaviours folder)")
    if args.duration is not None and args.duration <= 0:
        p.error("--duration must be > 0")
    for option in ("--robot-timeout-ms", "--live-robot-timeout-ms"):
        value = getattr(args, option[2:].replace("-", "_"))
        if value is not None and value <= 0:
            p.error(f"{option} must be > 0")
    for option in ("--tick-timeout-ms", "--snapshot-every"):
        value = getattr(args, option[2:].replace("-", "_"))
        if value is not None and value < 0:
            p.error(f"{option} must be >= 0")
    if args.restart_dead and args.mode == "free":
        p.error("--restart-dead needs lockstep or realtime mode: in free mode the world never marks a "
                "silent robot inactive, so a restarted shim could not take it over")
    if args.in_process:
        for option, given in (("--mode", args.mode != "lockstep"), ("--restart-dead", args.restart_dead),
                              ("--robot-timeout-ms", args.robot_timeout_ms is not None),
                              ("--live-robot-timeout-ms", args.live_robot_timeout_ms is not None)):
            if given:
                p.error(f"--in-process plays lockstep in one process: {option} does not apply")
    return args


def team_behaviour(spec: str, runswift_dir: Path | None = None) -> list | None:
    """robot_shim's behaviour options for a --team spec (LANG:SKILL[,KEY=VALUE...]), or
    None if it is malformed. runswift:SKILL runs the folder `runswift_dir`; plugin:PATH:NAME
    the behaviour NAME of the library PATH (made absolute: the shims may run elsewhere)."""
    head, *assignments = spec.split(",")
    language, _, skill = head.partition(":")
    if language not in ("py", "cpp", "runswift", "plugin") or not skill or (":" in skill) != (language == "plugin"):
        return None
    if any("=" not in a or a.startswith("=") for a in assignments):
        return None
    params = [arg for a in assignments for arg in ("--param", a)]
    if language == "plugin":  # plugin:PATH:NAME: a team's own C++ library (README, "Your own C++ behaviour")
        path, _, name = skill.rpartition(":")
        if not path or not name:
            return None
        return ["--behaviour-plugin", str(Path(path).resolve()), "--behaviour", name, *params]
    if language == "py":
        return ["--behaviour", "py", "--param", f"skill={skill}", *params]
    if language == "runswift":
        return ["--behaviour", "runswift", "--python-dir", str(runswift_dir), "--param", f"skill={skill}", *params]
    return ["--behaviour", skill, *params]


def match_options(a: argparse.Namespace) -> list:
    """The match's options both world programs take (sim_world, touchline_match): config,
    team size, duration, overrides, seed, and the launcher's --log-level for their lines."""
    return ["--config", a.config, "--set", f"match.team_size={a.team_size}",
            *(["--duration", a.duration] if a.duration else []),
            *[arg for item in a.set for arg in ("--set", item)], "--seed", a.seed, "--log-level", a.log_level]


def world_options(a: argparse.Namespace) -> list:
    """sim_world's options for the match (its --check takes the same)."""
    return [*match_options(a), "--mode", a.mode, "--speed", a.speed,
            *(["--robot-timeout-ms", a.robot_timeout_ms] if a.robot_timeout_ms else []),
            *(["--live-robot-timeout-ms", a.live_robot_timeout_ms] if a.live_robot_timeout_ms else []),
            "--lcm-url", a.lcm_url]


def robot_behaviour(a: argparse.Namespace, team: int, target: tuple) -> list:
    """robot_shim's behaviour options for a robot of `team`; `target` (x, y, theta) is its
    kick-off spot, which the goto behaviour walks to."""
    spec = getattr(a, f"team{team}")
    if spec:
        behaviour = team_behaviour(spec, a.runswift_dir)
    elif a.behaviour == "goto":
        x, y, theta = target
        return ["--behaviour", "goto", "--param", f"x={x:.0f}", "--param", f"y={y:.0f}", "--param", f"theta={theta:.3f}"]
    else:
        behaviour = ["--behaviour", "py", "--param", f"skill={a.skill}"]
    if a.python_dir and behaviour[:2] == ["--behaviour", "py"]:
        behaviour += ["--python-dir", a.python_dir]
    return behaviour


def shim_command(a: argparse.Namespace, bin_shim: Path, team: int, player: int, behaviour: list) -> list:
    """One robot_shim's command line in the match."""
    engine = getattr(a, f"walk_engine{team}") or a.walk_engine
    passed = []
    for option, keywords in SHIM_OPTIONS:
        if option == "--python-dir":
            continue  # for the Python behaviour only (robot_behaviour)
        value = getattr(a, option[2:].replace("-", "_"))
        if keywords.get("action") == "store_true":
            passed += [option] if value else []
        elif value is not None:
            passed += [option, value]
    # touchline_match's robots have no bus, and their lines are touchline_match's
    bus = [] if a.in_process else ["--lcm-url", a.lcm_url, "--log-level", a.log_level]
    return [bin_shim, "--team", team, "--player", player, "--walk-config", a.walk_config, "--walk-engine", engine,
            "--field-config", a.config, *bus, *(["--data-dir", a.data_dir] if a.data_dir else []),
            *passed, *behaviour]


def preflight(a: argparse.Namespace):
    """Checks every input before anything starts (match_checks.py); the match's plan (its
    planned length), or BadInput with one line."""
    bin_world, bin_shim = a.build_dir / "bin" / "sim_world", a.build_dir / "bin" / "robot_shim"
    for b in (bin_world, bin_shim):
        if not b.exists():
            raise BadInput(f"{b} not found; build first (tools/setup)")
    # In process, touchline_match --print-match checks the world config (and there is no bus to open).
    plan = None if a.in_process else check_world(bin_world, world_options(a))
    checks_robots = not a.in_process  # robot_shim --check opens the bus; touchline_match checks its robots itself
    for team in (0, 1):
        spec = getattr(a, f"team{team}")
        what = f"--team{team} {spec}" if spec else f"--skill {a.skill}" if a.behaviour == "py" else "--behaviour goto"
        behaviour = robot_behaviour(a, team, (0.0, 0.0, 0.0))
        if behaviour[:2] == ["--behaviour", "py"]:  # the skill is made when the robot first ticks: check it now
            skill = behaviour[behaviour.index("--param") + 1].partition("=")[2]
            check_python_skill(what, skill, a.python_dir or touchline_paths.behaviour_py())
        if checks_robots:
            check_robot(bin_shim, what, shim_command(a, bin_shim, team, 1, behaviour)[1:])
    return plan


def kickoff_targets(match) -> list:
    """Each team's formation in its own frame (the robot API's: +x towards the opponent
    goal), so both teams get the same targets, on the field the match (its match_config_t)
    is played on."""
    half_length, half_width = match.field_length_mm / 2, match.field_width_mm / 2
    targets = []
    for team in (0, 1):
        for player in range(1, match.team_size + 1):
            fx, fy, theta = FORMATION[player - 1]
            targets.append((team, player, fx * half_length, fy * half_width, theta))
    return targets


class StopSignal:
    """SIGINT and SIGTERM only note which came: the launcher then stops every process itself
    and exits with 128 + the signal, one line and no traceback."""

    def __init__(self):
        self.signum: int | None = None
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, self._note)

    def _note(self, signum: int, _frame) -> None:
        if self.signum is None:
            self.signum = signum


class Launcher:
    def __init__(self, args: argparse.Namespace, stop: StopSignal):
        self.args = args
        self.stop = stop
        self.logdir = Path(tempfile.mkdtemp(prefix="touchline-"))
        # A fresh secret per match for the authenticated bus, in the environment only: a
        # command line is readable by every user of the machine (ps).
        self.children = Children(self.logdir, {**os.environ, SECRET_ENV: secrets.token_hex(32)})

    def run(self) -> int:
        a = self.args
        bin_world = a.build_dir / "bin" / "sim_world"
        bin_shim = a.build_dir / "bin" / "robot_shim"
        bin_match = a.build_dir / "bin" / "touchline_match"
        for b in ((bin_match,) if a.in_process else (bin_world, bin_shim)):
            if not b.exists():
                logger.error(f"launch: {b} not found; build first (tools/setup)")
                return 2
        # The message types' Python: a build folder's, or an install prefix's (cmake --install).
        sys.path[:0] = touchline_paths.lcm_python_dirs(a.build_dir)
        log = None
        if not a.no_log:
            stamp = datetime.datetime.now().strftime("%Y-%m-%d_%H%M%S")
            log = a.log_dir / f"{stamp}_seed{a.seed}.lcmlog"
            log.parent.mkdir(parents=True, exist_ok=True)
        if a.in_process:
            try:
                rc = self.play_in_process(bin_match, log)
            finally:
                self.children.stop_all()
        else:
            watch = MatchWatch(a.lcm_url, progress=progress_kind(a), team_size=a.team_size,
                               plan=getattr(a, "plan", None))
            keeper = ShimKeeper(self.children, watch, restart=a.restart_dead)
            try:
                rc = self.play(bin_world, bin_shim, watch, keeper, log)
            finally:
                watch.stop()
                self.children.stop_all()
        if log and log.exists():
            logger.info(f"launch: match log {log} ({log.stat().st_size / 1e6:.1f} MB)")
        if rc == 0:  # the processes' own logs are kept only to explain a failure
            shutil.rmtree(self.logdir, ignore_errors=True)
        return rc

    def interrupted(self) -> int | None:
        if self.stop.signum is None:
            return None
        logger.error(f"launch: interrupted ({signal.Signals(self.stop.signum).name}), stopping every process")
        return 128 + self.stop.signum

    def play(self, bin_world: Path, bin_shim: Path, watch: MatchWatch, keeper: ShimKeeper, log: Path | None) -> int:
        a = self.args
        summary_path = self.logdir / "summary.json"
        world = self.children.start("sim_world", [bin_world, *world_options(a), "--summary", summary_path, "--quiet",
                                                  *(["--log", log] if log else [])])
        # The robots are placed on the field the world plays on (its config after every
        # --set), which only the world knows: it says so on TL_MATCH as it starts.
        if (rc := self.wait_for_match(world, watch)) is not None:
            return rc
        match = watch.match
        targets = kickoff_targets(match)
        for team, player, x, y, theta in targets:
            keeper.start(team, player, shim_command(a, bin_shim, team, player, robot_behaviour(a, team, (x, y, theta))))
        self.announce(match)
        kickoff_line = f"launch: kick-off, all {2 * match.team_size} robots joined"
        announced = False
        while world.poll() is None:
            if watch.kicked_off and not announced:  # from here on a dying shim no longer stops the match
                watch.say(kickoff_line)
                announced = True
            if (rc := self.interrupted()) is not None:
                return rc
            if watch.error:
                logger.error(f"launch: stopping the match: the match watcher failed: {watch.error} "
                             f"(logs in {self.logdir})")
                return EXIT_FAILED
            why = keeper.check(kicked_off=announced)
            if why:
                logger.error(f"launch: stopping the match: {why}")
                return EXIT_FAILED
            time.sleep(0.1)  # polling child exit codes, not hiding a race
        if world.poll() != 0:
            logger.error(f"launch: stopping the match: sim_world {world.why()} (logs in {self.logdir})")
            return EXIT_FAILED
        keeper.after_match(SHIMS_EXIT_S, lambda: self.stop.signum is not None)  # they end on FINISHED
        if watch.kicked_off and not announced:  # a match shorter than one look of the loop above
            watch.say(kickoff_line)
        watch.stop()  # the bar ends before the summary starts
        if (rc := self.interrupted()) is not None:
            return rc
        if not summary_path.exists():
            logger.error(f"launch: sim_world wrote no summary (logs in {self.logdir})")
            return EXIT_FAILED
        summary = json.loads(summary_path.read_text())  # the world's own word, score included: the bus may lie
        summary["events"] = [{"sim_s": t, "what": line} for t, line in sorted(watch.events + keeper.lines())]
        add_match_events(summary)
        summary["mode"] = a.mode
        summary["shim_deaths"] = keeper.summary()
        summary["launcher_malformed"] = dict(watch.malformed)
        self.report(summary, targets)
        if watch.malformed_total():
            print(f"  malformed messages the launcher ignored: "
                  + ", ".join(f"{channel} {n}" for channel, n in watch.malformed.items() if n)
                  + f" (last: {watch.last_malformed})")
        if keeper.deaths:
            print(f"  robot_shims that died: {len(keeper.deaths)} (their logs are in {self.logdir})")
        if a.json:
            a.json.write_text(json.dumps(summary, indent=2) + "\n")
        return EXIT_SHIM_DIED if keeper.deaths else 0

    def announce(self, match) -> None:
        a = self.args
        length = f"{a.duration:.0f} s simulated" if a.duration else "two halves"
        what = a.skill if a.behaviour == "py" else "goto kick-off spots"
        if a.team0 or a.team1:
            what = f"{a.team0 or what} v {a.team1 or what}"
        logger.info(f"launch: {2 * match.team_size} robots ({what}), {length}, {mode(a)} mode, seed {a.seed}, "
                    f"field {match.field_length_mm:.0f} x {match.field_width_mm:.0f} mm")

    def play_in_process(self, bin_match: Path, log: Path | None) -> int:
        """The match in one process (touchline_match): the robots' options as the shims would get
        them; its summary carries the match's events, which lockstep takes from the bus."""
        a = self.args
        world = [str(arg) for arg in [bin_match, *match_options(a)]]
        # The robots are placed on the field the match is played on (the config after every --set).
        described = subprocess.run([*world, "--print-match"], capture_output=True, text=True)
        if described.returncode != 0:
            logger.error(f"launch: {described.stderr.strip() or 'touchline_match --print-match failed'}")
            return described.returncode if described.returncode == 2 else EXIT_FAILED
        match = types.SimpleNamespace(**json.loads(described.stdout))
        targets = kickoff_targets(match)
        summary_path = self.logdir / "summary.json"
        argv = [*world, "--summary", summary_path, "--quiet", *(["--log", log] if log else [])]
        for team, player, x, y, theta in targets:
            argv += ["--", *shim_command(a, bin_match, team, player, robot_behaviour(a, team, (x, y, theta)))[1:]]
        self.announce(match)
        child = self.children.start("touchline_match", argv)
        while child.poll() is None:
            if (rc := self.interrupted()) is not None:
                return rc
            time.sleep(0.05)  # polling the child's exit code, not hiding a race
        if (rc := self.interrupted()) is not None:
            return rc
        if child.poll() != 0 or not summary_path.exists():
            logger.error(f"launch: touchline_match {child.why()} (logs in {self.logdir})")
            return 2 if child.poll() == 2 else EXIT_FAILED
        summary = json.loads(summary_path.read_text())
        summary["events"] = []  # robot trouble the world reports over the bus: none without one
        add_match_events(summary)
        summary["mode"] = "in-process"
        summary["shim_deaths"] = []
        summary["launcher_malformed"] = {}
        self.report(summary, targets)
        if a.json:
            a.json.write_text(json.dumps(summary, indent=2) + "\n")
        return 0

    def wait_for_match(self, world, watch: MatchWatch) -> int | None:
        """Waits for the world's TL_MATCH; an exit code if the match cannot go on without it."""
        deadline = time.monotonic() + MATCH_CONFIG_WAIT_S
        while watch.match is None:
            if (rc := self.interrupted()) is not None:
                return rc
            if world.poll() is not None:
                logger.error(f"launch: stopping the match: sim_world {world.why()} (logs in {self.logdir})")
                return EXIT_FAILED
            if watch.error or time.monotonic() > deadline:
                why = watch.error or (f"sim_world published no usable TL_MATCH (the match's set-up) within "
                                      f"{MATCH_CONFIG_WAIT_S} s" + (f" (last refused: {watch.last_malformed})"
                                                                     if watch.malformed["TL_MATCH"] else ""))
                logger.error(f"launch: stopping the match: {why} (logs in {self.logdir})")
                return EXIT_FAILED
            time.sleep(0.02)  # polling the watcher's thread, not hiding a race
        return None

    def report(self, summary: dict, targets: list) -> None:
        a = self.args
        print(f"Match: {summary['sim_s']:.0f} s simulated in {summary['wall_s']:.1f} s (x{summary['rtf']:.1f} real time), "
              f"{mode(a)} mode, seed {a.seed}, score {summary['score'][0]}:{summary['score'][1]}, "
              f"truth hash {summary['truth_hash']}")
        goals = ", ".join(f"team {g['team']} at {clock(g['sim_s'])}" for g in summary["goals"]) or "none"
        print(f"Goals: {goals}")
        kinds = {}
        for p in summary["penalties"]:
            kinds[p["kind"]] = kinds.get(p["kind"], 0) + 1
        print("Penalties: " + (", ".join(f"{k} {n}" for k, n in sorted(kinds.items())) or "none")
              + f"; falls: {len(summary['falls'])}")
        if summary["set_plays"]:
            set_plays = {}
            for play in summary["set_plays"]:  # "kick-in for team 1" -> "kick-in"
                name = play["what"].rsplit(" for team ", 1)[0]
                set_plays[name] = set_plays.get(name, 0) + 1
            print("Set plays: " + ", ".join(f"{k} {n}" for k, n in sorted(set_plays.items())))
        if summary["game_stuck"]:
            print(f"Game stuck: {len(summary['game_stuck'])} times (kick-off again), at "
                  + ", ".join(clock(s["sim_s"]) for s in summary["game_stuck"]))
        last = "kick-off spot off by" if a.behaviour == "goto" else ""
        print(f"{'robot':<12}{'answered':>9}{'missed':>7}{'behaviour CPU µs':>19}{'localisation rms':>20}"
              f"{'penalties':>10}   {'ended at (mm)':<16}{last}")
        for team, player, x, y, _ in targets:
            r = next((r for r in summary["robots"] if r["team"] == team and r["player"] == player), None)
            name = f"team {team} #{player}"
            if r is None:
                print(f"{name:<12}  never joined")
                continue
            cpu = f"{r['behaviour_cpu_us_mean']} mean {r['behaviour_cpu_us_max']} max"
            loc = f"{r['localisation_rms_mm']:.0f} mm {r['localisation_rms_rad']:.2f} rad"
            fouls = sum(1 for p in summary["penalties"] if p["team"] == team and p["player"] == player)
            where = f"({r['x_mm']:.0f}, {r['y_mm']:.0f})"
            off = ""
            if a.behaviour == "goto":  # targets are in the team's own frame; team 1's is turned by pi
                tx, ty = (x, y) if team == 0 else (-x, -y)
                off = f"{((r['x_mm'] - tx) ** 2 + (r['y_mm'] - ty) ** 2) ** 0.5:.0f} mm"
            print(f"{name:<12}{r['frames_answered']:>9}{r['frames_missed']:>7}{cpu:>19}{loc:>20}{fouls:>10}   "
                  f"{where:<16}{off}")
        for event in summary["events"]:
            print(f"  at {event['sim_s']:6.1f} s: {event['what']}")
        if summary["malformed"] or summary["stale"]:
            print(f"  malformed messages ignored: {summary['malformed']}, late answers dropped: {summary['stale']}")


def mode(args: argparse.Namespace) -> str:
    return "in-process" if args.in_process else args.mode


def add_match_events(summary: dict) -> None:
    """The summary's goals, penalties, falls, set plays and stuck games from its "match_events": the
    world's own record of what it published on TL_EVENT, which the bus may have dropped part of."""
    from touchline import match_event_t
    match_events = []
    for fields in summary.pop("match_events"):
        event = match_event_t()
        for key, value in fields.items():
            setattr(event, key, value)
        match_events.append(event)
    summary["goals"] = [{"sim_s": e.utime / 1e6, "team": e.team} for e in match_events if e.kind == e.GOAL]
    summary["penalties"] = [{"sim_s": e.utime / 1e6, "team": e.team, "player": e.player, "kind": e.text}
                            for e in match_events if e.kind == e.PENALTY]
    summary["falls"] = [{"sim_s": e.utime / 1e6, "team": e.team, "player": e.player}
                        for e in match_events if e.kind == e.FALL]
    summary["set_plays"] = [{"sim_s": e.utime / 1e6, "team": e.team, "what": e.text}
                            for e in match_events if e.kind == e.SET_PLAY and e.team >= 0]
    summary["game_stuck"] = [{"sim_s": e.utime / 1e6, "kickoff_team": e.team, "what": e.text}
                             for e in match_events if e.kind == e.GAME_STUCK]


def clock(sim_s: float) -> str:
    return f"{int(sim_s // 60)}:{int(sim_s % 60):02d}"


class LineHandler(logging.Handler):
    """The launcher's lines: info and debug to stdout, warnings and errors to stderr, each
    stream looked up per line, so that while a progress bar owns the terminal (and has taken
    both streams) the lines print above it."""

    def emit(self, record: logging.LogRecord) -> None:
        stream = sys.stderr if record.levelno >= logging.WARNING else sys.stdout
        stream.write(self.format(record) + "\n")
        stream.flush()


def setup_logging(level: str) -> None:
    logger.handlers[:] = [LineHandler()]
    logger.setLevel(level.upper())
    logger.propagate = False


def progress_kind(a: argparse.Namespace) -> str:
    """'bar' on a terminal, 'lines' (one every 10 % of the match) otherwise, or 'none'."""
    if a.no_progress:
        return "none"
    return "bar" if sys.stdout.isatty() else "lines"


def main(argv: list[str]) -> int:
    stop = StopSignal()  # first: a Ctrl-C from here on gives one line, never a traceback
    args = parse_args(argv)
    setup_logging(args.log_level)
    if not args.host_network and not args.in_process and os.environ.get("TOUCHLINE_IN_NETNS") != "1":
        # exec, not a child: tools/netns execs the launcher again in the namespace, so this
        # process stays the launcher and a signal sent to it (or to tools/match, which execs
        # this) stops the match instead of orphaning it.
        netns = Path(__file__).resolve().parent / "netns"  # beside this file, also when installed
        os.execv(netns, [str(netns), sys.executable, __file__, *argv])
    try:  # in the namespace: the checks open the match's bus as the programs will
        args.plan = preflight(args)
    except BadInput as e:
        logger.error(f"launch: {e}")
        return 2
    if stop.signum is not None:  # during the checks: nothing was started
        logger.error(f"launch: interrupted ({signal.Signals(stop.signum).name})")
        return 128 + stop.signum
    return Launcher(args, stop).run()


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except KeyboardInterrupt:  # only before main() set its handlers: nothing was started yet
        print("launch: interrupted", file=sys.stderr)
        sys.exit(130)
