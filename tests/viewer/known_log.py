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
]
SCORE = (2, 1)


def ball_at(k: int) -> tuple:
    return (200.0 + 40.0 * k, -300.0 + 15.0 * k)


def robot_at(spec, k: int) -> dict:
    team, player, active, x0, y0, th, dx, yaw, pitch = spec
    x, y = x0 + dx * k, y0
    lx, ly = -math.sin(th) * FOOT_OFFSET_MM, math.cos(th) * FOOT_OFFSET_MM
    return {"team": team, "player": player, "active": active, "body": (x, y, th),
            "left": (x + lx, y + ly, th), "right": (x - lx, y - ly, th), "head": (yaw, pitch)}


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
        t.body, t.left_foot, t.right_foot = _pose(r["body"]), _pose(r["left"]), _pose(r["right"])
        t.head_yaw_rad, t.head_pitch_rad = r["head"]
        m.robots.append(t)
    m.num_robots = len(m.robots)
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


def write_known_log(path: Path) -> Path:
    """FRAMES truth frames (one every 1/30 s), game states and statuses, in time order."""
    log = lcm.EventLog(str(path), "w", overwrite=True)
    events = [(0, "TL_GAME", _game(0, 600))]
    events += [(0, "TL_STATUS", _status(0, s[0], s[1], 2 if s[2] else 3)) for s in ROBOTS]
    events += [(utime_of(k), "TL_TRUTH", _truth(k)) for k in range(FRAMES)]
    events.append((utime_of(FRAMES // 2), "TL_GAME", _game(utime_of(FRAMES // 2), 599)))
    for utime, channel, message in sorted(events, key=lambda e: (e[0], e[1] != "TL_GAME")):
        log.write_event(WALL_US + utime, channel, message.encode())
    log.close()
    return path
