"""Possession and stuck time of a played match, from its LCM event log (the launcher's
recording). Reads the log's TL_MATCH (the field), TL_GAME (when the game is PLAYING),
TL_TRUTH (where every robot and the ball are) and TL_ACT_* (where each robot believes it and
the ball are); writes nothing.

  possession: at each sample, the nearest robot within POSSESSION_MM of the ball (playing,
              not penalised, not fallen) has it; its team counts the sample.
  stuck:      a robot that in the last 10 s of play stayed within STUCK_MOVE_MM of where
              it was at their start while turning more than a full turn (spinning), or
              while near the carpet's edge (pressed against the boundary), is stuck for
              that sample. A robot that walked away and back is not: it was not on the spot.
  ball moving: a sample in PLAYING whose ball is at least BALL_MOVING_MM from where it was
              a second before; its share of all samples of the match (set-up states, half
              time and stoppages count as not moving) is "ball_moving_share". A ball the
              referee put down (BALL_OUT, SET_PLAY) starts a new path there: the jump from
              where it went out is not a second of moving.
  playing:    the share of all samples in PLAYING, "playing_share": the most ball_moving_share
              can be, and its divisor for the share of play time the ball moved.
  contested:  a sample in PLAYING whose ball is not moving while robots of both teams (in
              play, standing) are within POSSESSION_MM of it: held between them, toe to toe;
              its share of all samples is "ball_contested_share".
  put back:   a sample in PLAYING from the referee's BALL_OUT (TL_EVENT) until the ball is
              first BALL_MOVING_MM from where it was put back (the first sample after the
              event) or PLAYING ends: the time a ball that went out costs the play; its share
              of all samples is "ball_put_back_still_share".
  ball belief: at each sample in PLAYING, for every robot within BALL_NEAR_MM of the ball
              that saw it in its last BALL_SEEN_FRAMES frames (its TL_ACT_<team>_<player> of
              that frame), how far the ball it believes lies from the true one, both relative
              to the robot (its believed pose against its true pose: the error it acts on,
              not the pose's); the median and 90th percentile over the match,
              "ball_belief_error_median_mm" and "ball_belief_error_p90_mm" (None: no sample).
"""
from __future__ import annotations

import math
import statistics
from collections import Counter, defaultdict
from pathlib import Path

SAMPLE_EVERY = 3                   # truth frames: 10 Hz is plenty for these statistics
SAMPLES_PER_S = 30 // SAMPLE_EVERY
STUCK_WINDOW = 10 * SAMPLES_PER_S  # samples
STUCK_MOVE_MM = 150                # staying this near the window's first position...
SPIN_RAD = 2 * math.pi             # ...while turning more than a full turn: spinning
WALL_MARGIN_MM = 250               # ...or within this of the carpet's edge: against a wall
POSSESSION_MM = 300                # the nearest robot this close to the ball has it
BALL_MOVING_MM = 100               # the ball this far from where it was 1 s before is moving:
                                   # a rolling ball or a dribble, not one wedged between feet
BALL_NEAR_MM = 400                 # robots this near the ball count for the ball belief ...
BALL_SEEN_FRAMES = 5               # ... if they saw it within this many frames


def analyse_log(log: Path) -> dict:
    """Possession samples per team, stuck seconds per team, the ball's shares (moving,
    playing, contested, put back) and the robots' ball belief error, from the truth stream
    and the robots' acts, on the field of the match's own TL_MATCH (the
    first message of its log). Needs the generated LCM types (build/lcm_types/gen/python) on
    sys.path; a log without TL_MATCH before its first TL_TRUTH raises ValueError."""
    import lcm
    from touchline import act_t, game_state_t, match_config_t, match_event_t, world_truth_t

    playing = False
    sampled = {}  # this sample's truth of each (team, player) in play, while PLAYING
    sampled_ball = None  # this sample's ball (x, y)
    sampled_utime = None
    belief_errors = []
    put_back = None  # None; "out": a BALL_OUT seen, its spot not yet; (x, y): where the ball was put
    put_back_samples = 0
    possession = Counter()
    history = defaultdict(list)  # (team, player) -> [(x, y, theta, counts)]
    stuck_frames = Counter()
    edge_x = edge_y = None  # the carpet's edges, from TL_MATCH
    truth_frames = 0
    ball_path = []  # the ball's last SAMPLES_PER_S + 1 samples
    placed = False  # the referee put the ball down since the last sample: its path starts again
    samples = moving_samples = playing_samples = contested_samples = 0
    for event in lcm.EventLog(str(log), "r"):
        if event.channel == "TL_MATCH" and edge_x is None:
            match = match_config_t.decode(event.data)
            edge_x, edge_y = (size / 2 + match.border_mm for size in (match.field_length_mm, match.field_width_mm))
            continue
        if event.channel == "TL_GAME":
            playing = game_state_t.decode(event.data).state == game_state_t.PLAYING
            put_back = put_back if playing else None
            continue
        if event.channel == "TL_EVENT":
            kind = match_event_t.decode(event.data).kind
            if kind == match_event_t.BALL_OUT:
                put_back = "out"
            placed = placed or kind in (match_event_t.BALL_OUT, match_event_t.SET_PLAY)
            continue
        if event.channel.startswith("TL_ACT_"):
            act = act_t.decode(event.data)
            truth_robot = sampled.get((act.team, act.player))
            if act.utime == sampled_utime and truth_robot is not None:
                error = ball_belief_error_mm(act, truth_robot, sampled_ball)
                if error is not None:
                    belief_errors.append(error)
            continue
        if event.channel != "TL_TRUTH":
            continue
        if edge_x is None:
            raise ValueError(f"{log} has no TL_MATCH before its first TL_TRUTH")
        truth_frames += 1
        if truth_frames % SAMPLE_EVERY:
            continue
        truth = world_truth_t.decode(event.data)
        sampled_utime = truth.utime
        sampled_ball = (truth.ball_x_mm, truth.ball_y_mm)
        sampled = {(r.team, r.player): r for r in truth.robots if playing and r.active and not r.penalised}
        samples += 1
        ball_path = [*([] if placed else ball_path[-SAMPLES_PER_S:]), (truth.ball_x_mm, truth.ball_y_mm)]
        placed = False
        moving = playing and ball_moving(ball_path)
        moving_samples += moving
        playing_samples += playing
        nearest = None
        near_teams = set()
        for r in truth.robots:
            counts = playing and r.active and not r.penalised and not r.fallen
            if add_sample(history[(r.team, r.player)], r, counts, edge_x, edge_y) is not None:
                stuck_frames[r.team] += 1
            d = math.hypot(r.body.x_mm - truth.ball_x_mm, r.body.y_mm - truth.ball_y_mm)
            if counts and d < POSSESSION_MM:
                near_teams.add(r.team)
                if nearest is None or d < nearest[0]:
                    nearest = (d, r.team)
        if nearest:
            possession[nearest[1]] += 1
        contested_samples += playing and not moving and len(near_teams) == 2
        if put_back == "out":
            put_back = (truth.ball_x_mm, truth.ball_y_mm)
        if put_back is not None:
            if math.hypot(truth.ball_x_mm - put_back[0], truth.ball_y_mm - put_back[1]) >= BALL_MOVING_MM:
                put_back = None
            else:
                put_back_samples += playing
    return {"possession_frames": [possession[0], possession[1]],
            "stuck_s": [stuck_frames[0] / SAMPLES_PER_S, stuck_frames[1] / SAMPLES_PER_S],
            "ball_moving_share": moving_samples / samples if samples else 0.0,
            "playing_share": playing_samples / samples if samples else 0.0,
            "ball_contested_share": contested_samples / samples if samples else 0.0,
            "ball_put_back_still_share": put_back_samples / samples if samples else 0.0,
            "ball_belief_error_median_mm": statistics.median(belief_errors) if belief_errors else None,
            "ball_belief_error_p90_mm": p90(belief_errors) if belief_errors else None}


def ball_belief_error_mm(act, robot, ball: tuple) -> float | None:
    """How far (mm) the ball robot `act` believes lies from the true `ball` (x, y), both
    relative to the robot: its believed ball from its believed pose against the true ball
    from its truth `robot`. None when the robot is not within BALL_NEAR_MM of the ball or has
    not seen it within BALL_SEEN_FRAMES frames."""
    body = robot.body
    if math.hypot(ball[0] - body.x_mm, ball[1] - body.y_mm) >= BALL_NEAR_MM or act.ball_lost_frames > BALL_SEEN_FRAMES:
        return None
    believed = relative(act.localised.x_mm, act.localised.y_mm, act.localised.theta_rad, act.ball_x_mm, act.ball_y_mm)
    true = relative(body.x_mm, body.y_mm, body.theta_rad, *ball)
    return math.hypot(believed[0] - true[0], believed[1] - true[1])


def relative(x: float, y: float, theta: float, px: float, py: float) -> tuple:
    """The field point (px, py) in the frame of a robot at (x, y) facing theta (x ahead)."""
    c, s = math.cos(theta), math.sin(theta)
    return (c * (px - x) + s * (py - y), -s * (px - x) + c * (py - y))


def p90(values: list) -> float:
    """The 90th percentile of two or more `values` (statistics' inclusive method, numpy's
    default); of one, that value."""
    return statistics.quantiles(values, n=10, method="inclusive")[-1] if len(values) > 1 else values[0]


def add_sample(h: list, r, counts: bool, edge_x: float, edge_y: float) -> str | None:
    """Appends robot truth `r`'s sample to its history `h` (the last STUCK_WINDOW + 1 kept)
    and says how it is stuck ("spin", "wall", None): only a robot that counted (in play, on
    the field, standing) for the whole window can be."""
    h.append((r.body.x_mm, r.body.y_mm, r.body.theta_rad, counts))
    kind = (stuck_kind(h, edge_x, edge_y) if counts and len(h) > STUCK_WINDOW
            and all(c for *_, c in h[-STUCK_WINDOW:]) else None)
    if len(h) > STUCK_WINDOW + 1:
        del h[0]
    return kind


def ball_moving(path: list) -> bool:
    """Whether the ball whose last samples (x, y) end `path` has moved BALL_MOVING_MM in the
    last second (SAMPLES_PER_S samples back; a shorter path has not)."""
    if len(path) <= SAMPLES_PER_S:
        return False
    (x0, y0), (x1, y1) = path[-SAMPLES_PER_S - 1], path[-1]
    return math.hypot(x1 - x0, y1 - y0) >= BALL_MOVING_MM


def stuck_kind(h: list, edge_x: float, edge_y: float) -> str | None:
    """How the robot whose samples end `h` is stuck over the last STUCK_WINDOW samples:
    "spin", "wall", or None when it is not."""
    window = h[-STUCK_WINDOW:]
    x0, y0 = window[0][:2]
    if math.hypot(window[-1][0] - x0, window[-1][1] - y0) >= STUCK_MOVE_MM:
        return None  # the common case, at once: it ended that far away
    if max(math.hypot(x - x0, y - y0) for x, y, *_ in window) >= STUCK_MOVE_MM:
        return None
    turned = sum(abs(math.remainder(b[2] - a[2], 2 * math.pi)) for a, b in zip(window, window[1:]))
    if turned > SPIN_RAD:
        return "spin"
    at_wall = min(min(edge_x - abs(x), edge_y - abs(y)) for x, y, *_ in window) < WALL_MARGIN_MM
    return "wall" if at_wall else None


EPISODE_GAP_S = 5.0  # s: stuck samples this close together are one episode (the test flickers at its limits)
ROLE_NAMES = {1: "goalie", 2: "striker", 3: "defender", 4: "midfielder"}  # team_comm.py's role byte


def message_role(act) -> str | None:
    """The role named in the team message an act_t carries (team_comm.py's byte 2), or None
    when it carries none (the robot keeps the role of its last message)."""
    if act.team_message_size < 3:
        return None
    return ROLE_NAMES.get(act.team_message[2], str(act.team_message[2]))


def stuck_episodes(log: Path) -> list[dict]:
    """Every stuck episode of a match (for finding why robots get stuck): a robot's run of
    stuck samples, as analyse_log counts them, from the start of its first window (time_s,
    simulated seconds since the log's first TL_TRUTH) to its last stuck sample (length_s),
    gaps up to EPISODE_GAP_S included,
    with its team, player, kind (of the first sample: spin or wall), the role of its last
    team message before the episode (team_comm.py's byte 2; "" without messages) and, at
    the episode's start, its believed ball_lost_frames and its pose (truth and believed), and
    the most its feet's headings differed during it (max_twist_rad: near pi, the feet face apart
    and their mean heading flips, which counts as turning)."""
    import lcm
    from touchline import act_t, game_state_t, match_config_t, world_truth_t

    playing = False
    history = defaultdict(list)
    acts = {}  # (team, player) -> [role, ball_lost_frames, believed (x, y, theta)]
    open_runs = {}  # (team, player) -> the episode being extended
    episodes = []
    edge_x = edge_y = t0 = None
    truth_frames = 0
    for event in lcm.EventLog(str(log), "r"):
        if event.channel == "TL_MATCH" and edge_x is None:
            match = match_config_t.decode(event.data)
            edge_x, edge_y = (size / 2 + match.border_mm for size in (match.field_length_mm, match.field_width_mm))
        elif event.channel == "TL_GAME":
            playing = game_state_t.decode(event.data).state == game_state_t.PLAYING
        elif event.channel.startswith("TL_ACT_"):
            act = act_t.decode(event.data)
            state = acts.setdefault((act.team, act.player), ["", 0, None])
            state[0] = message_role(act) or state[0]
            state[1:] = [act.ball_lost_frames, (act.localised.x_mm, act.localised.y_mm, act.localised.theta_rad)]
        elif event.channel == "TL_TRUTH":
            truth_frames += 1
            if truth_frames % SAMPLE_EVERY:
                continue
            truth = world_truth_t.decode(event.data)
            t0 = truth.utime if t0 is None else t0
            t = (truth.utime - t0) / 1e6
            for r in truth.robots:
                key = (r.team, r.player)
                counts = playing and r.active and not r.penalised and not r.fallen
                h = history[key]
                kind = add_sample(h, r, counts, edge_x, edge_y)
                run = open_runs.get(key)
                twist = abs(math.remainder(r.left_foot.theta_rad - r.right_foot.theta_rad, 2 * math.pi))
                if run:
                    run["max_twist_rad"] = max(run["max_twist_rad"], round(twist, 2))
                if kind is None:
                    if run and t - run["time_s"] - run["length_s"] > EPISODE_GAP_S:
                        del open_runs[key]
                elif run:
                    run["length_s"] = round(t - run["time_s"], 1)
                else:
                    role, lost, believed = acts.get(key, ["", 0, None])
                    start = t - STUCK_WINDOW / SAMPLES_PER_S
                    open_runs[key] = {"team": r.team, "player": r.player, "kind": kind, "role": role,
                                      "time_s": round(start, 1), "length_s": round(t - start, 1),
                                      "ball_lost_frames": lost, "truth": (round(h[-1][0]), round(h[-1][1])),
                                      "believed": believed and (round(believed[0]), round(believed[1])),
                                      "max_twist_rad": round(twist, 2)}
                    episodes.append(open_runs[key])
    if t0 is None:
        raise ValueError("holds no TL_TRUTH: not a match log")
    return episodes


def main(argv: list[str] | None = None) -> int:
    """Lists the stuck episodes of the LCM logs named on the command line, longest first; a
    log that cannot be read is one line and exit status 1."""
    import argparse
    import sys

    import touchline_paths
    from touchline_version import add_version_option
    parser = argparse.ArgumentParser(description="Lists every stuck episode of match logs, longest first.")
    add_version_option(parser, "tools/match_stats.py")
    parser.add_argument("logs", nargs="+", type=Path)
    parser.add_argument("--build-dir", type=Path, default=touchline_paths.build_dir())
    args = parser.parse_args(argv)
    sys.path[:0] = touchline_paths.lcm_python_dirs(args.build_dir)
    for log in args.logs:
        try:
            episodes = stuck_episodes(log)
        except (OSError, ValueError) as e:
            print(f"match_stats: {log}: {getattr(e, 'strerror', None) or e}", file=sys.stderr)
            return 1
        for e in sorted(episodes, key=lambda e: -e["length_s"]):
            print(f"{log}: team {e['team']} #{e['player']} {e['role'] or '-'} {e['kind']} at {e['time_s']:.1f} s "
                  f"for {e['length_s']:.1f} s, ball lost {e['ball_lost_frames']} frames, at {e['truth']} "
                  f"believing {e['believed']}, feet twisted up to {e['max_twist_rad']} rad")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
