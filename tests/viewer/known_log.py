"""A small lcm-logger log with known robot and ball positions, written for the viewer tests."""
import math
from pathlib import Path

import lcm

from touchline_viewer.decode import ROLES as ROLES_BY_CODE, TEAM_COMM
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
LEDS = {(0, 2): 0xFF00FF, (1, 1): 0x00FF00}  # chest LEDs (magenta: a failed behaviour); the rest off
# The match's TL_MATCH: deliberately not the SPL 2011 sizes, so a page that drew from its own
# copy of a config would be caught.
MATCH = {"field_length_mm": 7000.0, "field_width_mm": 4500.0, "border_mm": 600.0, "line_width_mm": 50.0,
         "goal_width_mm": 1500.0, "goal_depth_mm": 450.0, "goal_post_diameter_mm": 100.0,
         "goal_box_length_mm": 650.0, "goal_box_width_mm": 2300.0, "penalty_area_length_mm": 0.0,
         "penalty_area_width_mm": 0.0, "penalty_mark_distance_mm": 1900.0, "centre_circle_diameter_mm": 1300.0,
         "ball_diameter_mm": 80.0, "foot_length_mm": 170.0, "foot_width_mm": 90.0, "foot_separation_mm": 100.0,
         "camera_field_of_view_rad": 1.0, "camera_min_pitch_rad": -0.6, "camera_max_pitch_rad": 0.5,
         "camera_near_range_mm": 1100.0, "camera_range_span_mm": 2500.0,
         "sonar_range_mm": 900.0, "sonar_half_width_mm": 100.0}
SEED, TEAM_SIZE = 17, 4
# match_event_t: (utime, kind, team, player, text); the page shows them as (kind name, text)
GOAL_US = 9 * FRAME_US + 2000  # during frame 9
EVENTS = [(0, 0, -1, 0, "PLAYING"), (0, 2, 1, 4, "pushing"), (FALL_US, 4, 0, 2, "fell"), (GOAL_US, 1, 0, 2, "goal")]

# Each robot's belief in its act_t (TL_ACT_<team>_<player>): its pose off the truth by
# BELIEF_OFFSET_MM, the position covariance [xx, xy, yy] (mm^2), the ball off the truth by
# BALL_BELIEF_OFFSET_MM, and the role its team message names (our Team's format, team_comm.py's, sent
# every ROLE_EVERY_FRAMES frames from frame 0). The inactive robot sends nothing; the penalised
# one sends a message of another format: it has a belief but no role.
BELIEF_OFFSET_MM = (150.0, -100.0)
BALL_BELIEF_OFFSET_MM = (100.0, 80.0)
COVARIANCES = {(0, 1): (40000.0, 0.0, 10000.0), (0, 2): (22500.0, 0.0, 22500.0), (1, 1): (30000.0, 15000.0, 30000.0),
               (1, 2): (2500.0, 0.0, 90000.0), (1, 3): (0.0, 0.0, 0.0), (1, 4): (10000.0, 0.0, 10000.0)}
ROLES = {(0, 1): "goalie", (0, 2): "striker", (1, 1): "goalie", (1, 2): "defender", (1, 3): "midfielder"}
ROLE_CODES = {name: code for code, name in ROLES_BY_CODE.items()}
ROLE_EVERY_FRAMES = 6
BALL_LOST_FRAMES = {(1, 2): 60}  # the rest saw it this frame


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


def camera_range_mm(pitch: float) -> float:
    """The camera's reach for a head pitch, as the world computes it (sim/src/camera.cpp)."""
    lo, hi = MATCH["camera_min_pitch_rad"], MATCH["camera_max_pitch_rad"]
    return MATCH["camera_near_range_mm"] + MATCH["camera_range_span_mm"] * (hi - min(max(pitch, lo), hi)) / (hi - lo)


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
        t.chest_led = LEDS.get((t.team, t.player), 0)
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


def match_config(**changes):
    """The known match's TL_MATCH (match_config_t), with `changes` to its fields."""
    m = touchline.match_config_t()
    m.utime, m.types_version, m.seed, m.team_size = 0, m.TYPES_VERSION, SEED, TEAM_SIZE
    m.duration_s, m.referee, m.half_s = 1800.0, True, 600.0
    for key, value in {**MATCH, **changes}.items():
        setattr(m, key, value)
    return m


def belief_at(team: int, player: int, k: int) -> dict:
    """What robot (team, player) believes in frame k, as its act_t says it (None: no act)."""
    if (team, player) not in COVARIANCES:
        return None
    spec = next(s for s in ROBOTS if s[:2] == (team, player))
    x, y, th = robot_at(spec, k)["body"]
    bx, by = ball_at(k)
    return {"pose": (x + BELIEF_OFFSET_MM[0], y + BELIEF_OFFSET_MM[1], th), "cov": COVARIANCES[(team, player)],
            "ball": (bx + BALL_BELIEF_OFFSET_MM[0], by + BALL_BELIEF_OFFSET_MM[1]),
            "ball_lost": BALL_LOST_FRAMES.get((team, player), 0), "role": ROLES.get((team, player))}


def team_message(team: int, player: int, k: int) -> bytes:
    if k % ROLE_EVERY_FRAMES:
        return b""
    role = ROLES.get((team, player))
    if role is None:
        return b"\x07\x07\x07\x07"  # another behaviour's message: no role in it
    return TEAM_COMM.encodeMessage(TEAM_COMM.makeTeamInfo(player, ROLE_CODES[role], True, False, False, 272, 0, 0))


def _act(k: int, team: int, player: int):
    """Robot (team, player)'s answer to frame k, sent before the frame's truth."""
    b, m = belief_at(team, player, k), touchline.act_t()
    m.utime, m.frame, m.team, m.player, m.instance, m.motion_ticks = utime_of(k - 1), k, team, player, 7, 0
    m.left, m.right = [], []
    m.localised = _pose(b["pose"])
    m.localised_cov_mm2 = list(b["cov"])
    m.ball_x_mm, m.ball_y_mm = b["ball"]
    m.ball_lost_frames = b["ball_lost"]
    m.team_message = team_message(team, player, k)
    m.team_message_size = len(m.team_message)
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
    events = [(0, "TL_MATCH", match_config()), (0, "TL_GAME", _game(0, 600))]
    events += [(0, "TL_STATUS", _status(0, s[0], s[1], 2 if s[2] else 3)) for s in ROBOTS]
    events += [(e[0], "TL_EVENT", _event(*e)) for e in EVENTS]
    for k in range(FRAMES):
        events += [(utime_of(k - 1), "TL_SENSE", _sense(k))] if k in SENSE_FRAMES else []
        events += [(utime_of(k - 1), f"TL_ACT_{t}_{p}", _act(k, t, p)) for t, p in sorted(COVARIANCES)]
        events.append((utime_of(k), "TL_TRUTH", _truth(k)))
    events.append((utime_of(FRAMES // 2), "TL_GAME", _game(utime_of(FRAMES // 2), 599)))
    events.append((utime_of(FRAMES // 2), "TL_MATCH", match_config()))  # the world repeats it
    first = {"TL_MATCH": 0, "TL_GAME": 1}  # as sim_world: TL_MATCH first of all, the game before frames
    return sorted(events, key=lambda e: (e[0], first.get(e[1], 2)))


def write_known_log(path: Path) -> Path:
    log = lcm.EventLog(str(path), "w", overwrite=True)
    for utime, channel, message in known_messages():
        log.write_event(WALL_US + utime, channel, message.encode())
    log.close()
    return path
