"""decode.py: a robot's belief from its act_t, and its role from our Team behaviours' team
message (10 bytes, version 1, role in byte 2); anything else names no role, and a belief that
is not finite is left out rather than sent to the page as NaN (which JSON cannot carry)."""
import json
import math

import pytest

from known_log import _act, belief_at
from touchline_viewer.decode import act_belief, decode, role_in_message


@pytest.mark.parametrize("message,role", [
    (bytes([1, 3, 2, 0, 0, 0, 0, 0, 0, 0]), "striker"), (bytes([1, 1, 1, 0, 0, 0, 0, 0, 0, 0]), "goalie"),
    (bytes([1, 2, 3, 0, 0, 0, 0, 0, 0, 0]), "defender"), (bytes([1, 4, 4, 0, 0, 0, 0, 0, 0, 0]), "midfielder"),
    (bytes([1, 4, 0, 0, 0, 0, 0, 0, 0, 0]), None), (bytes([1, 4, 9, 0, 0, 0, 0, 0, 0, 0]), None),
    (bytes([2, 3, 2, 0, 0, 0, 0, 0, 0, 0]), None), (bytes([1, 3, 2, 0]), None), (b"", None)],
    ids=["striker", "goalie", "defender", "midfielder", "none", "unknown", "other-version", "other-size", "empty"])
def test_the_role_is_read_from_our_team_message_only(message, role):
    assert role_in_message(message) == role


def test_an_act_gives_the_robot_s_belief():
    b, want = act_belief(_act(0, 0, 2).encode()), belief_at(0, 2, 0)
    assert (b["team"], b["player"], b["frame"], b["role"]) == (0, 2, 0, "striker")
    assert b["pose"] == pytest.approx(list(want["pose"]), abs=0.06)
    assert (b["cov"], b["ball"], b["ball_lost"]) == (list(want["cov"]), list(want["ball"]), 0)
    assert decode("TL_ACT_0_2", _act(0, 0, 2).encode()) == b, "TL_ACT_<team>_<player> decodes to the belief"


def test_a_belief_that_is_not_finite_is_left_out():
    m = _act(0, 1, 1)
    m.localised_cov_mm2 = [math.nan, 0.0, 1.0]
    m.ball_x_mm = math.inf
    b = act_belief(m.encode())
    assert (b["cov"], b["ball"]) == (None, None) and b["pose"] is not None
    json.loads(json.dumps(b, allow_nan=False))  # what the page gets is valid JSON
