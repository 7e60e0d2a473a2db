"""Writes a TileQ as a policy file (format v1, docs/learning/policy_format.md) for the
deployed skills, and reads one back into a TileQ (to evaluate or go on training), with the
robots' own writer and reader (behaviour_py/skills/tile_policy.py)."""
import math

import numpy as np

from touchline_rl.native import touchline_sim
from touchline_rl.robot_skills import loadPolicy, policyText


def write_policy(path, q, success_distance_mm=50.0, success_heading_rad=math.radians(10.0), comments=()):
    """Writes the TileQ `q` with the robots' own writer (skills/tile_policy.py)."""
    coding = q.coding
    tiles = (coding.tiles_distance, coding.tiles_bearing, coding.tiles_heading)
    weights = np.asarray(q.weights).tolist()  # float32 -> float exactly: the same %.9g text
    text = policyText(coding.distance_scale_mm, coding.max_distance_mm, coding.tilings, tiles, success_distance_mm,
                      success_heading_rad, q.actions, weights, comments)
    with open(path, "w") as out:
        out.write(text)


def read_policy(path):
    """(TileQ, success_distance_mm, success_heading_rad), parsed by the robots' own reader
    (behaviour_py/skills/tile_policy.py): a file they would refuse is refused here too, with
    the same one-line ValueError naming the file."""
    policy = loadPolicy(str(path))
    coding = touchline_sim.TileCodingDef()
    coding.distance_scale_mm, coding.max_distance_mm = policy.distanceScale, policy.maxDistance
    coding.tilings = policy.tilings
    coding.tiles_distance, coding.tiles_bearing, coding.tiles_heading = policy.tilesU, policy.tilesB, policy.tilesH
    q = touchline_sim.TileQ(coding, [tuple(a) for a in policy.actions])
    q.weights[:] = np.array(policy.weights, dtype=np.float32)
    return q, policy.successDistance, policy.successHeading
