#!/usr/bin/env python3
"""Writes a synthetic go-to-pose policy file (format v1, docs/learning/policy_format.md): a
hand-made stand-in for the learned policy, for trying the learned walker (walker=learned)
and recording the port-regression corpus before a trained policy exists.

Each cell's weights come from a one-step lookahead at the cell's centre: the action that
leaves the target nearest (and, close in, best turned to its heading) after
LOOKAHEAD_S seconds scores highest. It walks to a pose, not well; nothing is learned.

  tools/synthetic_policy.py /tmp/data/policies/go_to_pose.policy
  tools/match --data-dir /tmp/data --team0 cpp:Team,walker=learned
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import touchline_paths
from touchline_version import add_version_option

sys.path.append(str(touchline_paths.behaviour_py()))
from skills.tile_policy import policyText, wrapAngle as wrap  # noqa: E402 (the format's one writer, the one wrap)

TILINGS = 4
TILES = (10, 16, 16)            # distance (log), bearing, heading error
DISTANCE_SCALE_MM = 100.0
MAX_DISTANCE_MM = 12000.0
SUCCESS_DISTANCE_MM = 50.0
SUCCESS_HEADING_RAD = 0.17453
LOOKAHEAD_S = 0.4
ACTIONS = (                      # forward mm/s, left mm/s, turn rad/s
    (300.0, 0.0, 0.0), (150.0, 0.0, 0.0), (60.0, 0.0, 0.0), (-100.0, 0.0, 0.0),
    (150.0, 0.0, 0.6), (150.0, 0.0, -0.6), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0),
    (0.0, 0.0, 0.3), (0.0, 0.0, -0.3), (0.0, 150.0, 0.0), (0.0, -150.0, 0.0),
)


def cost(x: float, y: float, heading: float) -> float:
    """How far from done the robot-relative target (x, y, heading error) is."""
    d = math.hypot(x, y)
    bearing = math.atan2(y, x) if d > 0 else 0.0
    return d / 200.0 + (1.5 if d > 500.0 else 0.3) * abs(bearing) + 2.0 * 300.0 / (300.0 + d) * abs(heading)


def score(x: float, y: float, heading: float, action: tuple) -> float:
    forward, left, turn = (v * LOOKAHEAD_S for v in action)
    x, y = x - forward, y - left
    c, s = math.cos(turn), math.sin(turn)
    return -cost(c * x + s * y, c * y - s * x, wrap(heading - turn))


def cell_centre(k: int, iu: int, ib: int, ih: int) -> tuple:
    """The robot-relative state at the centre of tiling k's cell (iu, ib, ih)."""
    tiles_u, tiles_b, tiles_h = TILES
    u_max = math.log(1.0 + MAX_DISTANCE_MM / DISTANCE_SCALE_MM)
    su = min(max(iu + 0.5 - k * 1 / TILINGS, 0.0), tiles_u)
    d = DISTANCE_SCALE_MM * (math.exp(su / tiles_u * u_max) - 1.0)
    bearing = (ib + 0.5 - k * 3 / TILINGS) / tiles_b * 2 * math.pi - math.pi
    heading = wrap((ih + 0.5 - k * 5 / TILINGS) / tiles_h * 2 * math.pi - math.pi)
    return d * math.cos(bearing), d * math.sin(bearing), heading


def policy_text() -> str:
    tiles_u, tiles_b, tiles_h = TILES
    weights = []
    for k in range(TILINGS):
        for iu in range(tiles_u + 1):
            for ib in range(tiles_b):
                for ih in range(tiles_h):
                    state = cell_centre(k, iu, ib, ih)
                    weights += [score(*state, action) / TILINGS for action in ACTIONS]
    return policyText(DISTANCE_SCALE_MM, MAX_DISTANCE_MM, TILINGS, TILES, SUCCESS_DISTANCE_MM, SUCCESS_HEADING_RAD,
                      ACTIONS, weights, ["synthetic: one-step lookahead at the cell centres (tools/synthetic_policy.py)"])


def write_policy(path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(policy_text())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_version_option(parser, "tools/synthetic_policy.py")
    parser.add_argument("out", type=Path, help="the policy file to write (e.g. DATA_DIR/policies/go_to_pose.policy)")
    write_policy(parser.parse_args().out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
