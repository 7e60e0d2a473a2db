"""The match's geometry for the page, from its TL_MATCH message (match_config_t): the sizes the
world plays with, overrides included, so a match on another field is drawn as it is played."""
import math

from .lcm_types import import_touchline

MATCH = "TL_MATCH"
_types = import_touchline()
TYPES_VERSION = _types.match_config_t.TYPES_VERSION
FIELD_KEYS = ("border_mm", "line_width_mm", "goal_width_mm", "goal_depth_mm", "goal_post_diameter_mm",
              "goal_box_length_mm", "goal_box_width_mm", "penalty_area_length_mm", "penalty_area_width_mm",
              "penalty_mark_distance_mm", "centre_circle_diameter_mm")
CAMERA_KEYS = ("field_of_view_rad", "min_pitch_rad", "max_pitch_rad", "near_range_mm", "range_span_mm")


def match_dict(data: bytes) -> dict:
    """The page's `match`: field, ball, feet, camera and sonar sizes, team size and seed.
    Raises ValueError for a message that decodes but cannot be drawn."""
    m = _types.match_config_t.decode(data)
    if m.types_version != TYPES_VERSION:
        raise ValueError(f"types version {m.types_version}, not {TYPES_VERSION}")
    match = {
        "seed": m.seed % 2 ** 64, "team_size": m.team_size, "duration_s": m.duration_s,
        "field": {"length_mm": m.field_length_mm, "width_mm": m.field_width_mm,
                  **{key: getattr(m, key) for key in FIELD_KEYS}},
        "ball_diameter_mm": m.ball_diameter_mm,
        "foot": {"length_mm": m.foot_length_mm, "width_mm": m.foot_width_mm, "separation_mm": m.foot_separation_mm},
        "camera": {key: getattr(m, "camera_" + key) for key in CAMERA_KEYS},
        "sonar": {"range_mm": m.sonar_range_mm, "half_width_mm": m.sonar_half_width_mm},
    }
    sizes = [m.field_length_mm, m.field_width_mm, m.ball_diameter_mm, m.foot_length_mm, m.foot_width_mm]
    if not all(math.isfinite(v) and v > 0 for v in sizes) or m.border_mm < 0:
        raise ValueError("a field, ball or foot size that is not a positive length")
    if not m.camera_min_pitch_rad < m.camera_max_pitch_rad:
        raise ValueError("camera pitch limits out of order")
    return match


def written_version(data: bytes):
    """The types version of the program that wrote a TL_MATCH message, read even when this
    build cannot decode it (match_config_t keeps it in bytes 16-17), or None."""
    return int.from_bytes(data[16:18], "big") if len(data) >= 18 else None


def missing_match_reason(name: str, undecodable: bytes = None) -> str:
    """One line for a log whose TL_MATCH this viewer cannot use (None: it has none)."""
    if undecodable is None:
        return (f"log {name} has no {MATCH} (the match's geometry): it was recorded by a Touchline older than "
                f"LCM types version {TYPES_VERSION}, whose messages this viewer cannot read; "
                f"replay it with the viewer of that version")
    version = written_version(undecodable)
    if version == TYPES_VERSION:
        return f"log {name}: its {MATCH} (the match's geometry) is corrupt or cannot be drawn"
    return (f"log {name} was recorded with Touchline's LCM types version {version}; "
            f"this viewer reads version {TYPES_VERSION}: replay it with the viewer of that version")
