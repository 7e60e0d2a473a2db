"""Writes a TileQ as a policy file (format v1, docs/learning/policy_format.md) for the
deployed skills, and reads one back into a TileQ (to evaluate or go on training)."""
import math

import numpy as np

from touchline_rl.native import touchline_sim

MAGIC = "touchline-policy 1"


def write_policy(path, q, success_distance_mm=50.0, success_heading_rad=math.radians(10.0), comments=()):
    coding = q.coding
    lines = [MAGIC]
    lines += [f"# {c}" for c in comments]
    lines += [
        "features polar-log",
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
    """(TileQ, success_distance_mm, success_heading_rad). ValueError naming the file."""
    with open(path) as source:
        text = source.read()
    header, _, body = text.partition("\nweights ")
    lines = [line.strip() for line in header.splitlines() if line.strip() and not line.startswith("#")]
    if not lines or lines[0] != MAGIC:
        raise ValueError(f"{path}: not a {MAGIC!r} file")
    keys, actions = {}, []
    for line in lines[1:]:
        key, *values = line.split()
        if key == "action":
            actions.append(tuple(float(v) for v in values))
        else:
            keys[key] = values
    try:
        coding = touchline_sim.TileCodingDef()
        coding.distance_scale_mm = float(keys["distance_scale_mm"][0])
        coding.max_distance_mm = float(keys["max_distance_mm"][0])
        coding.tilings = int(keys["tilings"][0])
        coding.tiles_distance, coding.tiles_bearing, coding.tiles_heading = (int(v) for v in keys["tiles"])
        count, *numbers = body.split()
        q = touchline_sim.TileQ(coding, actions)
        if int(count) != len(numbers) or len(numbers) != q.weights.size:
            raise ValueError(f"{len(numbers)} weights for {q.weights.size}")
        q.weights[:] = np.array(numbers, dtype=np.float32)
        return q, float(keys["success_distance_mm"][0]), float(keys["success_heading_rad"][0])
    except (KeyError, ValueError) as error:
        raise ValueError(f"{path}: bad policy file ({error})") from None
