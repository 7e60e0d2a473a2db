"""decode.py: a robot's belief from its act_t, and its role from our Team behaviours' team
message (behaviour_py/skills/team_comm.py's format, whatever its version); anything else names no role, and a belief that
is not finite is left out rather than sent to the page as NaN (which JSON cannot carry)."""
import json
import math

import pytest

from known_log import _act, belief_at
from touchline_viewer.decode import TEAM_COMM, act_belief, decode, role_in_message


def message(role, version_change=0, size_change=0):
    """A team message of our Team behaviours naming `role` (team_comm's own encoder)."""
    data = bytearray(TEAM_COMM.encodeMessage(TEAM_COMM.makeTeamInfo(3, role, True, False, False, 400, 10, -20)))
    data[0] += version_change
    return bytes(data[:len(data) + size_change])


@pytest.mark.parametrize("data,role", [
    (message(TEAM_COMM.ROLE_STRIKER), "striker"), (message(TEAM_COMM.ROLE_GOALIE), "goalie"),
    (message(TEAM_COMM.ROLE_DEFENDER), "defender"), (message(TEAM_COMM.ROLE_MIDFIELDER), "midfielder"),
    (message(TEAM_COMM.ROLE_NONE), None), (message(9), None), (message(TEAM_COMM.ROLE_STRIKER, version_change=1), None),
    (message(TEAM_COMM.ROLE_STRIKER, size_change=-4), None), (b"", None)],
    ids=["striker", "goalie", "defender", "midfielder", "none", "unknown", "other-version", "other-size", "empty"])
def test_the_role_is_read_from_our_team_message_only(data, role):
    assert role_in_message(data) == role


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
