"""LCM messages (TL_MATCH, TL_TRUTH, TL_SENSE, TL_GAME, TL_STATUS, TL_EVENT) to the JSON-ready
dicts the page draws."""
import struct

from .field import MATCH, match_dict
from .lcm_types import import_touchline

TRUTH, SENSE, GAME, STATUS, EVENT = "TL_TRUTH", "TL_SENSE", "TL_GAME", "TL_STATUS", "TL_EVENT"
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


DECODERS = {MATCH: match_dict, TRUTH: truth_dict, SENSE: sense_dict, GAME: game_dict, STATUS: status_dict, EVENT: event_dict}


def decode(channel: str, data: bytes):
    """The message as a dict, or None for another channel or a message that does not decode."""
    decoder = DECODERS.get(channel)
    if decoder is None:
        return None
    try:
        return decoder(data)
    except (ValueError, IndexError, TypeError, UnicodeDecodeError, struct.error):
        return None
