"""Policy files for the learned-walker tests: a small deterministic policy whose greedy
action is known by hand, written where the skills look for it.

The test policy: 2 tilings of 4 x 8 x 8 tiles, three actions (forward 300 mm/s, turn left
1 rad/s, turn right 1 rad/s). Each cell's weights depend on its bearing tile ib alone:
forward 1 when ib is 3 or 4 (the target about ahead), left 0.5 when ib >= 5, right 0.5
when ib <= 2. tests/behaviour_cpp/skills/policy_files.hpp writes the same file.
"""
import pytest
import robot

TEST_TILINGS = 2
TEST_TILES = (4, 8, 8)
TEST_ACTIONS = ((300.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0))


def bearingWeight(ib, action):
    if action == 0:
        return 1.0 if ib in (3, 4) else 0.0
    if action == 1:
        return 0.5 if ib >= 5 else 0.0
    return 0.5 if ib <= 2 else 0.0


def policyText(weight=bearingWeight, tilings=TEST_TILINGS, tiles=TEST_TILES, actions=TEST_ACTIONS, header=None):
    """A policy file: weight(ib, action) for every cell; header: the lines before the
    weights instead of the test policy's (to break one)."""
    tilesU, tilesB, tilesH = tiles
    weights = [weight(ib, a)
               for _ in range(tilings) for _ in range(tilesU + 1) for ib in range(tilesB) for _ in range(tilesH)
               for a in range(len(actions))]
    if header is None:
        header = ["touchline-policy 1", "# the go-to-pose test policy (tests/behaviour_py/policy_files.py)",
                  "features polar-log", "distance_scale_mm 100", "max_distance_mm 12000",
                  "tilings %d" % tilings, "tiles %d %d %d" % tiles, "success_distance_mm 50",
                  "success_heading_rad 0.17453", "actions %d" % len(actions)]
        header += ["action %.9g %.9g %.9g" % action for action in actions]
        header.append("weights %d" % len(weights))
    body = ["".join("%.9g " % w for w in weights[i:i + 8]).rstrip() for i in range(0, len(weights), 8)]
    return "\n".join(header + body) + "\n"


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
