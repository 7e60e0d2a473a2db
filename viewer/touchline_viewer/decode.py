"""LCM messages (TL_MATCH, TL_TRUTH, TL_SENSE, TL_GAME, TL_STATUS, TL_EVENT, TL_ACT_<team>_<player>)
to the JSON-ready dicts the page draws."""
import importlib.util
import math
import struct

from .field import MATCH, match_dict
from .home import touchline_paths
from .lcm_types import import_touchline

TRUTH, SENSE, GAME, STATUS, EVENT = "TL_TRUTH", "TL_SENSE", "TL_GAME", "TL_STATUS", "TL_EVENT"
ACT_PATTERN = "TL_ACT_.*"  # each robot's answer: its belief and its team message
CHANNELS = (MATCH, TRUTH, SENSE, GAME, STATUS, EVENT)
STATUS_NAMES = {1: "JOINED", 2: "ACTIVE", 3: "TIMED_OUT", 4: "REJOINED", 5: "REJECTED"}
EVENT_KINDS = {0: "STATE_CHANGE", 1: "GOAL", 2: "PENALTY", 3: "RELEASED", 4: "FALL", 5: "BALL_OUT", 6: "SET_PLAY", 7: "GAME_STUCK"}
RECENT_EVENTS = 5  # the latest match events each frame carries for the HUD

_types = import_touchline()


def _pose(p) -> list:
    return [round(p.x_mm, 1), round(p.y_mm, 1), round(p.theta_rad, 4)]


def truth_dict(data: bytes) -> dict:
    m = _types.world_truth_t.decode(data)
    return {
        "utime": m.utime, "frame": m.frame,
        "ball": [round(m.ball_x_mm, 1), round(m.ball_y_mm, 1), round(m.ball_vx_mm_s, 1), round(m.ball_vy_mm_s, 1)],
        "robots": [{"team": r.team, "player": r.player, "active": bool(r.active),
                    "penalised": bool(r.penalised), "fallen": bool(r.fallen),
                    "body": _pose(r.body), "left": _pose(r.left_foot), "right": _pose(r.right_foot),
                    "head": [round(r.head_yaw_rad, 4), round(r.head_pitch_rad, 4)],
                    "led": f"#{r.chest_led & 0xFFFFFF:06x}"} for r in m.robots],
    }


def sense_dict(data: bytes) -> dict:
    """Only each robot's sonar (fractions of the range, 1: nothing): the rest is the robots' input."""
    m = _types.sense_t.decode(data)
    return {"utime": m.utime, "frame": m.frame,
            "robots": [{"team": r.team, "player": r.player,
                        "sonar": [round(r.sonar_left, 3), round(r.sonar_right, 3)]} for r in m.robots]}


def game_dict(data: bytes) -> dict:
    m = _types.game_state_t.decode(data)
    return {"utime": m.utime, "state": m.state, "secs_remaining": m.secs_remaining,
            "first_half": bool(m.first_half), "kickoff_team": m.kickoff_team, "score": list(m.score)}


def status_dict(data: bytes) -> dict:
    m = _types.robot_status_t.decode(data)
    return {"utime": m.utime, "team": m.team, "player": m.player,
            "state": STATUS_NAMES.get(m.state, str(m.state)),
            "frames_answered": m.frames_answered, "frames_missed": m.frames_missed,
            "cpu_mean_us": m.behaviour_cpu_us_mean, "cpu_max_us": m.behaviour_cpu_us_max, "detail": m.detail}


def event_dict(data: bytes) -> dict:
    m = _types.match_event_t.decode(data)
    return {"utime": m.utime, "kind": EVENT_KINDS.get(m.kind, str(m.kind)), "team": m.team,
            "player": m.player, "text": m.text}


# The role a robot plays, as our Team behaviours say it in every team message they send in
# act_t.team_message (every 6 frames, 5 Hz). The format is behaviour_py/skills/team_comm.py's
# own (plain Python, no robot module): the viewer reads it with the robots' own decoder, so it
# follows any new version of the message. A behaviour that sends no such message has no role.
def _team_comm():
    path = touchline_paths.behaviour_py() / "skills" / "team_comm.py"
    spec = importlib.util.spec_from_file_location("touchline_viewer_team_comm", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


TEAM_COMM = _team_comm()
ROLES = {TEAM_COMM.ROLE_GOALIE: "goalie", TEAM_COMM.ROLE_STRIKER: "striker", TEAM_COMM.ROLE_DEFENDER: "defender",
         TEAM_COMM.ROLE_MIDFIELDER: "midfielder"}


def role_in_message(message: bytes):
    """The role named in a team message of our Team behaviours, or None (another format, or none)."""
    info = TEAM_COMM.decodeMessage(bytes(message))
    return ROLES.get(info.role) if info else None


def _finite(*values) -> bool:
    return all(math.isfinite(v) for v in values)


def act_belief(data: bytes) -> dict:
    """What a robot believes in the frame its act_t answers (field frame): its pose, the position
    covariance (xx, xy, yy, mm^2; all 0 with perfect localisation), the ball and the frames since
    it saw it; `pose`, `cov` or `ball` is None where the robot sent something not finite. `role`:
    the role its team message names, None without one (the caller keeps the last)."""
    m = _types.act_t.decode(data)
    p, cov = m.localised, list(m.localised_cov_mm2)
    return {"team": m.team, "player": m.player, "frame": m.frame,
            "pose": _pose(p) if _finite(p.x_mm, p.y_mm, p.theta_rad) else None,
            "cov": [round(v, 1) for v in cov] if _finite(*cov) else None,
            "ball": [round(m.ball_x_mm, 1), round(m.ball_y_mm, 1)] if _finite(m.ball_x_mm, m.ball_y_mm) else None,
            "ball_lost": m.ball_lost_frames, "role": role_in_message(bytes(m.team_message))}


DECODERS = {MATCH: match_dict, TRUTH: truth_dict, SENSE: sense_dict, GAME: game_dict, STATUS: status_dict, EVENT: event_dict}


def decode(channel: str, data: bytes):
    """The message as a dict, or None for another channel or a message that does not decode."""
    decoder = DECODERS.get(channel) or (act_belief if channel.startswith("TL_ACT_") else None)
    if decoder is None:
        return None
    try:
        return decoder(data)
    except (ValueError, IndexError, TypeError, UnicodeDecodeError, struct.error):
        return None
