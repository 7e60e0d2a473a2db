"""Policy files for the learned-walker tests: a small deterministic policy whose greedy
action is known by hand, written where the skills look for it.

The test policy: 2 tilings of 4 x 8 x 8 tiles, three actions (forward 300 mm/s, turn left
1 rad/s, turn right 1 rad/s). Each cell's weights depend on its bearing tile ib alone:
forward 1 when ib is 3 or 4 (the target about ahead), left 0.5 when ib >= 5, right 0.5
when ib <= 2. tests/behaviour_cpp/skills/policy_files.hpp writes the same file.
"""
import pytest
import robot
from skills.tile_policy import policyText as formatPolicy

TEST_TILINGS = 2
TEST_TILES = (4, 8, 8)
TEST_ACTIONS = ((300.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0))


def bearingWeight(ib, action):
    if action == 0:
        return 1.0 if ib in (3, 4) else 0.0
    if action == 1:
        return 0.5 if ib >= 5 else 0.0
    return 0.5 if ib <= 2 else 0.0


def policyText(weight=bearingWeight, tilings=TEST_TILINGS, tiles=TEST_TILES, actions=TEST_ACTIONS):
    """A policy file with weight(ib, action) for every cell, written by the format's own
    writer (skills/tile_policy.py)."""
    tilesU, tilesB, tilesH = tiles
    weights = [weight(ib, a)
               for _ in range(tilings) for _ in range(tilesU + 1) for ib in range(tilesB) for _ in range(tilesH)
               for a in range(len(actions))]
    return formatPolicy(100.0, 12000.0, tilings, tiles, 50.0, 0.17453, actions, weights,
                        ["the go-to-pose test policy (tests/behaviour_py/policy_files.py)"])


def writePolicy(path, text=None):
    """Writes `text` (default: the test policy) to path, making its folder; returns str(path)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(policyText() if text is None else text)
    return str(path)


@pytest.fixture
def dataDir(tmp_path):
    """A robot data directory holding the test policy at policies/go_to_pose.policy, in force
    for the test."""
    writePolicy(tmp_path / "policies" / "go_to_pose.policy")
    previous = robot.data_dir()
    robot.set_data_dir(str(tmp_path))
    yield tmp_path
    robot.set_data_dir(previous)
