"""Writes a TileQ as a policy file (format v1, docs/learning/policy_format.md) for the
deployed skills, and reads one back into a TileQ (to evaluate or go on training) with the
robots' own reader."""
import math
import sys

import numpy as np

from touchline_rl.native import REPO, touchline_sim

if str(REPO / "behaviour_py") not in sys.path:
    sys.path.append(str(REPO / "behaviour_py"))
from skills.tile_policy import FEATURES_POLAR_LOG, POLICY_MAGIC, POLICY_VERSION, loadPolicy  # noqa: E402


def write_policy(path, q, success_distance_mm=50.0, success_heading_rad=math.radians(10.0), comments=()):
    coding = q.coding
    lines = [f"{POLICY_MAGIC} {POLICY_VERSION}"]
    lines += [f"# {c}" for c in comments]
    lines += [
        f"features {FEATURES_POLAR_LOG}",
        f"distance_scale_mm {coding.distance_scale_mm:.9g}",
        f"max_distance_mm {coding.max_distance_mm:.9g}",
        f"tilings {coding.tilings}",
        f"tiles {coding.tiles_distance} {coding.tiles_bearing} {coding.tiles_heading}",
        f"success_distance_mm {success_distance_mm:.9g}",
        f"success_heading_rad {success_heading_rad:.9g}",
        f"actions {len(q.actions)}",
    ]
    lines += [f"action {f:.9g} {left:.9g} {turn:.9g}" for f, left, turn in q.actions]
    weights = np.asarray(q.weights)
    lines.append(f"weights {weights.size}")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")
        for row in range(0, weights.size, 8):
            out.write(" ".join(f"{w:.9g}" for w in weights[row:row + 8]) + "\n")


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
