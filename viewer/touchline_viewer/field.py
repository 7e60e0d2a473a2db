"""Field geometry for the page, read from a world config (config/spl2011.ini's format)."""
import configparser
from pathlib import Path

from .errors import ViewerError

# The code's defaults (the SPL 2011 field); every key is optional in the config.
FIELD_DEFAULTS = {
    "length_mm": 6000, "width_mm": 4000, "border_mm": 700, "line_width_mm": 50,
    "goal_width_mm": 1400, "goal_depth_mm": 500, "goal_post_diameter_mm": 100,
    "goal_box_length_mm": 600, "goal_box_width_mm": 2200,
    "penalty_area_length_mm": 0, "penalty_area_width_mm": 0,
    "penalty_mark_distance_mm": 1800, "centre_circle_diameter_mm": 1200,
}
PHYSICS_DEFAULTS = {"ball_diameter_mm": 65, "foot_length_mm": 160, "foot_width_mm": 90}


def load_field(path: Path) -> dict:
    """The [field] lengths and the ball and foot sizes from [physics], in millimetres."""
    parser = configparser.ConfigParser(inline_comment_prefixes=("#", ";"))
    try:
        with open(path, encoding="utf-8") as f:
            parser.read_file(f)
    except OSError as e:
        raise ViewerError(f"cannot read config {path}: {e.strerror or e}") from None
    except configparser.Error as e:
        raise ViewerError(f"bad config {path}: {e}") from None
    field = {}
    for section, defaults in (("field", FIELD_DEFAULTS), ("physics", PHYSICS_DEFAULTS)):
        for key, default in defaults.items():
            raw = parser.get(section, key, fallback=None)
            try:
                field[key] = float(raw) if raw is not None else float(default)
            except ValueError:
                raise ViewerError(f"bad config {path}: [{section}] {key} = {raw!r} is not a number") from None
    if field["length_mm"] <= 0 or field["width_mm"] <= 0:
        raise ViewerError(f"bad config {path}: the field length and width must be > 0")
    return field
