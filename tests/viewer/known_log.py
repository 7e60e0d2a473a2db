"""A small lcm-logger log with known robot and ball positions, written for the viewer tests."""
import math
from pathlib import Path

import lcm

from touchline_viewer.lcm_types import import_touchline

touchline = import_touchline()

FRAMES = 12
FRAME_US = 33333
WALL_US = 1_700_000_000_000_000  # event timestamps: wall clock, unused by the viewer
FOOT_OFFSET_MM = 50  # feet sit this far left and right of the body
# (team, player, active, start x, start y, heading, x per frame, head yaw, head pitch)
ROBOTS = [
    (0, 1, True, -2500.0, 0.0, 0.0, 10.0, 0.0, 0.3),
    (0, 2, True, -1500.0, 800.0, 0.4, 30.0, 0.5, 0.0),
    (0, 3, False, -1200.0, -1100.0, -0.3, 0.0, 0.0, -0.2),
    (1, 1, True, 2500.0, 200.0, math.pi, -10.0, 0.0, 0.3),
    (1, 2, True, 1300.0, -700.0, 2.6, -30.0, -0.4, 0.1),
    (1, 3, True, 700.0, 1300.0, -1.9, -20.0, 0.3, 0.5),
    (1, 4, True, 2400.0, 2350.0, -math.pi / 2, 0.0, 0.0, 0.3),  # penalised, on the bench
]
SCORE = (2, 1)
PENALISED = {(1, 4)}  # in every frame
FALLEN_FROM = {(0, 2): 6}  # lying from this frame on
SENSE_FRAMES = range(FRAMES - 1)  # the last frame has no TL_SENSE: no sonar to draw
FALL_US = 6 * FRAME_US + 1000  # during frame 6, after frame 5's truth
# match_event_t: (utime, kind, team, player, text); the page shows them as (kind name, text)
EVENTS = [(0, 0, -1, 0, "PLAYING"), (0, 2, 1, 4, "pushing"), (FALL_US, 4, 0, 2, "fell")]


def ball_at(k: int) -> tuple:
    return (200.0 + 40.0 * k, -300.0 + 15.0 * k)


def robot_at(spec, k: int) -> dict:
    team, player, active, x0, y0, th, dx, yaw, pitch = spec
    x, y = x0 + dx * k, y0
    lx, ly = -math.sin(th) * FOOT_OFFSET_MM, math.cos(th) * FOOT_OFFSET_MM
    return {"team": team, "player": player, "active": active, "body": (x, y, th),
            "penalised": (team, player) in PENALISED, "fallen": k >= FALLEN_FROM.get((team, player), FRAMES),
            "left": (x + lx, y + ly, th), "right": (x - lx, y - ly, th), "head": (yaw, pitch)}


def sonar_at(team: int, player: int, k: int) -> tuple:
    """(left, right) sonar readings in frame k, fractions of the range; 1: nothing ahead."""
    if (team, player) == (1, 1):
        return (1.0, round(0.5 - 0.02 * k, 2))  # something closing in on the right
    return {(0, 1): (0.6, 1.0), (1, 2): (0.25, 0.3)}.get((team, player), (1.0, 1.0))


def utime_of(k: int) -> int:
    return (k + 1) * FRAME_US


def _pose(values):
    p = touchline.pose2d_t()
    p.x_mm, p.y_mm, p.theta_rad = values
    return p


def _truth(k: int):
    m = touchline.world_truth_t()
    m.utime, m.frame = utime_of(k), k
    m.ball_x_mm, m.ball_y_mm = ball_at(k)
    m.ball_vx_mm_s, m.ball_vy_mm_s = 1200.0, 450.0
    m.robots = []
    for spec in ROBOTS:
        r, t = robot_at(spec, k), touchline.robot_truth_t()
        t.team, t.player, t.active = r["team"], r["player"], r["active"]
        t.penalised, t.fallen = r["penalised"], r["fallen"]
        t.body, t.left_foot, t.right_foot = _pose(r["body"]), _pose(r["left"]), _pose(r["right"])
        t.head_yaw_rad, t.head_pitch_rad = r["head"]
        m.robots.append(t)
    m.num_robots = len(m.robots)
    return m


def _sense(k: int):
    """Frame k's sense, sent at the start of the frame (utime_of(k - 1)), before its truth."""
    m = touchline.sense_t()
    m.utime, m.frame = utime_of(k - 1), k
    m.robots = []
    for spec in ROBOTS:
        s = touchline.robot_sense_t()
        s.team, s.player, s.active = spec[:3]
        s.sonar_left, s.sonar_right = sonar_at(s.team, s.player, k)
        m.robots.append(s)
    m.num_robots = len(m.robots)
    return m


def _event(utime: int, kind: int, team: int, player: int, text: str):
    m = touchline.match_event_t()
    m.utime, m.kind, m.team, m.player, m.text = utime, kind, team, player, text
    return m


def _game(utime: int, secs: int):
    m = touchline.game_state_t()
    m.utime, m.state, m.secs_remaining, m.first_half, m.kickoff_team = utime, m.PLAYING, secs, 1, 0
    m.score = list(SCORE)
    return m


def _status(utime: int, team: int, player: int, state: int):
    m = touchline.robot_status_t()
    m.utime, m.team, m.player, m.state = utime, team, player, state
    m.frames_answered, m.frames_missed, m.detail = 10, 0 if state != 3 else 5, "known log"
    return m


def known_messages() -> list:
    """(utime, channel, message) in the order a match publishes them: FRAMES truth frames (one
    every 1/30 s), each after its sense, with game states, statuses and events in between."""
    events = [(0, "TL_GAME", _game(0, 600))]
    events += [(0, "TL_STATUS", _status(0, s[0], s[1], 2 if s[2] else 3)) for s in ROBOTS]
    events += [(e[0], "TL_EVENT", _event(*e)) for e in EVENTS]
    for k in range(FRAMES):
        events += [(utime_of(k - 1), "TL_SENSE", _sense(k))] if k in SENSE_FRAMES else []
        events.append((utime_of(k), "TL_TRUTH", _truth(k)))
    events.append((utime_of(FRAMES // 2), "TL_GAME", _game(utime_of(FRAMES // 2), 599)))
    return sorted(events, key=lambda e: (e[0], e[1] != "TL_GAME"))


def write_known_log(path: Path) -> Path:
    log = lcm.EventLog(str(path), "w", overwrite=True)
    for utime, channel, message in known_messages():
        log.write_event(WALL_US + utime, channel, message.encode())
    log.close()
    return path
