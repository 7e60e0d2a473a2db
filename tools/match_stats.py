"""Possession and stuck time of a played match, from its LCM event log (the launcher's
recording). Reads the log's TL_MATCH (the field), TL_GAME (when the game is PLAYING) and
TL_TRUTH (where every robot and the ball are); writes nothing.

  possession: at each sample, the nearest robot within POSSESSION_MM of the ball (playing,
              not penalised, not fallen) has it; its team counts the sample.
  stuck:      a robot that in the last 10 s of play moved less than STUCK_MOVE_MM net while
              turning more than a full turn (spinning), or stayed near the carpet's edge
              (pressed against the boundary), is stuck for that sample.
  ball moving: a sample in PLAYING whose ball is at least BALL_MOVING_MM from where it was
              a second before; its share of all samples of the match (set-up states, half
              time and stoppages count as not moving) is "ball_moving_share".
  playing:    the share of all samples in PLAYING, "playing_share": the most ball_moving_share
              can be, and its divisor for the share of play time the ball moved.
"""
from __future__ import annotations

import math
from collections import Counter, defaultdict
from pathlib import Path

SAMPLE_EVERY = 3                   # truth frames: 10 Hz is plenty for these statistics
SAMPLES_PER_S = 30 // SAMPLE_EVERY
STUCK_WINDOW = 10 * SAMPLES_PER_S  # samples
STUCK_MOVE_MM = 150                # net movement under this over the window...
SPIN_RAD = 2 * math.pi             # ...while turning more than a full turn: spinning
WALL_MARGIN_MM = 250               # ...or within this of the carpet's edge: against a wall
POSSESSION_MM = 300                # the nearest robot this close to the ball has it
BALL_MOVING_MM = 100               # the ball this far from where it was 1 s before is moving:
                                   # a rolling ball or a dribble, not one wedged between feet


def analyse_log(log: Path) -> dict:
    """Possession samples per team and stuck seconds per team, from the truth stream, on the
    field of the match's own TL_MATCH (the first message of its log). Needs the generated
    LCM types (build/lcm_types/gen/python) on sys.path; a log without TL_MATCH before its
    first TL_TRUTH raises ValueError."""
    import lcm
    from touchline import game_state_t, match_config_t, world_truth_t

    playing = False
    possession = Counter()
    history = defaultdict(list)  # (team, player) -> [(x, y, theta, counts)]
    stuck_frames = Counter()
    edge_x = edge_y = None  # the carpet's edges, from TL_MATCH
    truth_frames = 0
    ball_path = []  # the ball's last SAMPLES_PER_S + 1 samples
    samples = moving_samples = playing_samples = 0
    for event in lcm.EventLog(str(log), "r"):
        if event.channel == "TL_MATCH" and edge_x is None:
            match = match_config_t.decode(event.data)
            edge_x, edge_y = (size / 2 + match.border_mm for size in (match.field_length_mm, match.field_width_mm))
            continue
        if event.channel == "TL_GAME":
            playing = game_state_t.decode(event.data).state == game_state_t.PLAYING
            continue
        if event.channel != "TL_TRUTH":
            continue
        if edge_x is None:
            raise ValueError(f"{log} has no TL_MATCH before its first TL_TRUTH")
        truth_frames += 1
        if truth_frames % SAMPLE_EVERY:
            continue
        truth = world_truth_t.decode(event.data)
        samples += 1
        ball_path = [*ball_path[-SAMPLES_PER_S:], (truth.ball_x_mm, truth.ball_y_mm)]
        moving_samples += playing and ball_moving(ball_path)
        playing_samples += playing
        nearest = None
        for r in truth.robots:
            counts = playing and r.active and not r.penalised and not r.fallen
            h = history[(r.team, r.player)]
            h.append((r.body.x_mm, r.body.y_mm, r.body.theta_rad, counts))
            if counts and len(h) > STUCK_WINDOW and all(c for *_, c in h[-STUCK_WINDOW:]) and stuck(h, edge_x, edge_y):
                stuck_frames[r.team] += 1
            if len(h) > STUCK_WINDOW + 1:
                del h[0]
            d = math.hypot(r.body.x_mm - truth.ball_x_mm, r.body.y_mm - truth.ball_y_mm)
            if counts and d < POSSESSION_MM and (nearest is None or d < nearest[0]):
                nearest = (d, r.team)
        if nearest:
            possession[nearest[1]] += 1
    return {"possession_frames": [possession[0], possession[1]],
            "stuck_s": [stuck_frames[0] / SAMPLES_PER_S, stuck_frames[1] / SAMPLES_PER_S],
            "ball_moving_share": moving_samples / samples if samples else 0.0,
            "playing_share": playing_samples / samples if samples else 0.0}


def ball_moving(path: list) -> bool:
    """Whether the ball whose last samples (x, y) end `path` has moved BALL_MOVING_MM in the
    last second (SAMPLES_PER_S samples back; a shorter path has not)."""
    if len(path) <= SAMPLES_PER_S:
        return False
    (x0, y0), (x1, y1) = path[-SAMPLES_PER_S - 1], path[-1]
    return math.hypot(x1 - x0, y1 - y0) >= BALL_MOVING_MM


def stuck(h: list, edge_x: float, edge_y: float) -> bool:
    """Whether the robot whose samples end `h` is stuck over the last STUCK_WINDOW samples."""
    window = h[-STUCK_WINDOW:]
    moved = math.hypot(window[-1][0] - window[0][0], window[-1][1] - window[0][1])
    if moved >= STUCK_MOVE_MM:
        return False
    turned = sum(abs(math.remainder(b[2] - a[2], 2 * math.pi)) for a, b in zip(window, window[1:]))
    at_wall = min(min(edge_x - abs(x), edge_y - abs(y)) for x, y, *_ in window) < WALL_MARGIN_MM
    return turned > SPIN_RAD or at_wall
