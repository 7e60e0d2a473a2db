"""TilePolicy: the policy file format v1 read, its features, Q and greedy action; the same
worked numbers as tests/behaviour_cpp/skills/test_tile_policy.cpp.

The test policy (policy_files.py): 2 tilings of 4 x 8 x 8 tiles, distance scale 100 mm,
max 12000 mm, so u_max = log(121) and, per tiling k, the cell (iu, ib, ih) is
floor(su + k/2), floor(sb + 3k/2) mod 8, floor(sh + 5k/2) mod 8 and the weight index of
action 0 is 3 * (((5k + iu) * 8 + ib) * 8 + ih).
"""
import math

import numpy as np
import pytest
from policy_files import bearingWeight, policyText, writePolicy

from skills.tile_policy import (MAX_POLICY_WEIGHTS, PolicyError, cachedPolicy, loadPolicy, parsePolicy, policyText as
                                formatPolicy, wrapAngle)

FORWARD, LEFT, RIGHT = 0, 1, 2


@pytest.fixture
def policy():
    return parsePolicy(policyText(), "test.policy")


def test_what_the_writer_writes_reads_back_the_same():
    # float32 weights (as training holds them) come back as the same float32: %.9g is enough.
    some = [0.1, -2.5e-7, 3.4028234663852886e38, 1.0 / 3.0, 0.0, 7.0, -1e-30, 12345.678, 0.5]
    weights = [float(np.float32(w)) for w in some] * 8  # 2 tilings x (1 + 1) x 3 x 3 cells x 2 actions
    actions = [(300.0, 0.0, 0.25), (0.0, -150.0, 1.0)]
    text = formatPolicy(80.5, 9000.0, 2, (1, 3, 3), 45.0, 0.2, actions, weights, ["a comment", "another"])
    read = parsePolicy(text, "written.policy")
    assert (read.distanceScale, read.maxDistance, read.tilings) == (80.5, 9000.0, 2)
    assert (read.tilesU, read.tilesB, read.tilesH, read.successDistance, read.successHeading) == (1, 3, 3, 45.0, 0.2)
    assert read.actions == actions
    assert [float(np.float32(w)) for w in read.weights] == weights
    assert text.splitlines()[1:3] == ["# a comment", "# another"]


def test_reads_the_header_and_the_actions(policy):
    assert (policy.tilings, policy.tilesU, policy.tilesB, policy.tilesH) == (2, 4, 8, 8)
    assert (policy.distanceScale, policy.maxDistance) == (100.0, 12000.0)
    assert (policy.successDistance, policy.successHeading) == (50.0, 0.17453)
    assert policy.actions == [(300.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]
    assert len(policy.weights) == 2 * 5 * 8 * 8 * 3


# (x, y, theta) -> per tiling, the weight index of action 0; then Q and the greedy action.
WORKED = [
    # d = 1118.03: su = 4 log(12.1803) / log(121) = 2.085; b = 0.4636: sb = 4.590; sh = 4.637
    # k=0: (2, 4, 4) -> 3 * 164; k=1: (2, 6, 7) -> 3 * 503. ib 4: forward 1; ib 6: left 0.5.
    ((1000.0, 500.0, 0.5), [492, 1509], [1.0, 0.5, 0.0], FORWARD),
    # su = 1.855, b = 1.8158: sb = 6.312, h = 0: sh = 4 exactly. k=0: (1, 6, 4); k=1: (2, 7, 6).
    ((-200.0, 800.0, 0.0), [348, 1530], [0.0, 1.0, 0.0], LEFT),
    # su = 1.703, b = -2.0344: sb = 1.410. k=0: (1, 1, 4); k=1: (2, 2, 6).
    ((-300.0, -600.0, 0.0), [228, 1410], [0.0, 0.0, 1.0], RIGHT),
    # beyond max_distance_mm: u clamped, su = Tu = 4, the last of Tu + 1 cells. k=0: (4, 4, 4); k=1: (4, 5, 6).
    ((50000.0, 0.0, 0.0), [876, 1866], [1.0, 0.5, 0.0], FORWARD),
    # at the target: d = 0, bearing 0 by definition. k=0: (0, 4, 4); k=1: (0, 5, 6).
    ((0.0, 0.0, 0.0), [108, 1098], [1.0, 0.5, 0.0], FORWARD),
]


@pytest.mark.parametrize("state, indices, q, action", WORKED)
def test_worked_states(policy, state, indices, q, action):
    assert policy.cellIndices(*state) == indices
    assert policy.values(*state) == q
    assert policy.greedyAction(*state) == action


def test_heading_error_wraps(policy):
    assert policy.cellIndices(1000.0, 500.0, 0.5 + 2 * math.pi) == policy.cellIndices(1000.0, 500.0, 0.5)
    assert policy.cellIndices(1000.0, 500.0, 0.5 - 4 * math.pi) == policy.cellIndices(1000.0, 500.0, 0.5)
    assert wrapAngle(math.pi) == -math.pi
    assert wrapAngle(-math.pi) == -math.pi
    assert wrapAngle(1.5 * math.pi) == pytest.approx(-0.5 * math.pi)


def test_ties_go_to_the_lowest_action():
    policy = parsePolicy(policyText(weight=lambda ib, a: (0.0, 1.0, 1.0)[a]), "ties.policy")
    assert policy.values(1000.0, 500.0, 0.5) == [0.0, 2.0, 2.0]
    assert policy.greedyAction(1000.0, 500.0, 0.5) == LEFT


def test_arrived_inside_both_tolerances(policy):
    assert policy.arrived(30.0, -20.0, 0.1)       # 36 mm, 0.1 rad
    assert not policy.arrived(30.0, -20.0, 0.2)   # heading off
    assert not policy.arrived(60.0, 0.0, 0.0)     # too far
    assert policy.arrived(0.0, 0.0, 2 * math.pi)  # wrapped: on heading


def test_comments_blank_lines_and_crlf_are_read():
    text = policyText().replace("features polar-log\n", "\n# a comment\nfeatures polar-log\n").replace("\n", "\r\n")
    assert parsePolicy(text, "crlf.policy").greedyAction(-200.0, 800.0, 0.0) == LEFT


def broken(old, new):
    text = policyText()
    assert old in text
    return text.replace(old, new, 1)


BAD_FILES = [
    (broken("touchline-policy 1", "touchline-polcy 1"),
     "bad.policy: not a policy file (the first line must be 'touchline-policy 1')"),
    ("", "bad.policy: not a policy file (the first line must be 'touchline-policy 1')"),
    (broken("touchline-policy 1", "touchline-policy 2"),
     "bad.policy: policy format version '2' is not supported (this reader knows 1)"),
    (broken("tiles 4 8 8\n", ""), "bad.policy: missing 'tiles'"),
    (policyText().split("weights")[0], "bad.policy: missing 'weights'"),
    (broken("weights 1920", "weights 1919"),
     "bad.policy: 'weights' says 1919, but 2 tilings x 5 x 8 x 8 cells x 3 actions need 1920"),
    (policyText().rstrip("\n").rsplit(" ", 1)[0] + "\n", "bad.policy: 1919 weights after 'weights', expected 1920"),
    (broken("weights 1920\n0 0 0.5 0 0 0.5", "weights 1920\n0 0 0.5 0 0 zero"), "bad.policy: weight 5: 'zero' is not a number"),
    (broken("weights 1920\n0 0 0.5", "weights 1920\nnan 0 0.5"), "bad.policy: weight 0: 'nan' is not a number"),
    (broken("distance_scale_mm 100", "distance_scale_mm 1OO"),
     "bad.policy: line 4 (distance_scale_mm): '1OO' is not a number"),
    (broken("distance_scale_mm 100", "distance_scale_mm 0"), "bad.policy: 'distance_scale_mm' must be > 0 (got 0)"),
    (broken("tilings 2", "tilings 2.5"), "bad.policy: line 6 (tilings): '2.5' is not a whole number >= 1"),
    (broken("features polar-log", "features cartesian"),
     "bad.policy: line 3 (features): unknown feature kind 'cartesian' (known: polar-log)"),
    (broken("max_distance_mm 12000", "max_distance_mm 12000\nmax_distance_mm 6000"),
     "bad.policy: line 6 (max_distance_mm): 'max_distance_mm' given twice"),
    (broken("features polar-log", "feature polar-log"), "bad.policy: line 3 (feature): unknown key 'feature'"),
    (broken("action 0 0 -1\n", ""), "bad.policy: 2 'action' lines, but 'actions' says 3"),
    (broken("action 0 0 -1", "action 0 -1"), "bad.policy: line 13 (action): expected forward, left, turn"),
    (broken("tiles 4 8 8", "tiles 1000 1000 1000"), "bad.policy: 6006000000 weights is more than %d" % MAX_POLICY_WEIGHTS),
]


@pytest.mark.parametrize("text, message", BAD_FILES)
def test_bad_files_are_rejected_in_one_line(text, message):
    with pytest.raises(ValueError) as error:
        parsePolicy(text, "bad.policy")
    assert str(error.value) == message


def test_a_missing_file_is_named(tmp_path):
    path = str(tmp_path / "nowhere.policy")
    with pytest.raises(PolicyError) as error:
        loadPolicy(path)
    assert str(error.value) == path + ": cannot read the policy (No such file or directory)"


def test_a_file_is_read_once_per_path(tmp_path):
    path = writePolicy(tmp_path / "once.policy")
    first = cachedPolicy(path)
    writePolicy(tmp_path / "once.policy", "not a policy any more")
    assert cachedPolicy(path) is first


def test_the_bearing_rule_is_what_the_worked_numbers_assume():
    assert [bearingWeight(ib, FORWARD) for ib in range(8)] == [0, 0, 0, 1, 1, 0, 0, 0]
    assert [bearingWeight(ib, LEFT) for ib in range(8)] == [0, 0, 0, 0, 0, 0.5, 0.5, 0.5]
    assert [bearingWeight(ib, RIGHT) for ib in range(8)] == [0.5, 0.5, 0.5, 0, 0, 0, 0, 0]
