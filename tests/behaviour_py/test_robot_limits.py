"""robot_limits and camera: clamping to the walk and head limits, and the thesis camera range."""
import pytest

from skills import camera, robot_limits
from skills.robot_limits import MAX_HEAD_PITCH, MIN_HEAD_PITCH, clampTurn, clampWalk


def test_limits_are_the_walk_and_head_limits():
    assert (robot_limits.MAX_FORWARD, robot_limits.MAX_BACKWARD, robot_limits.MAX_LEFT) == (300.0, 200.0, 200.0)
    assert robot_limits.MAX_TURN == 1.5
    assert (robot_limits.MAX_HEAD_YAW, MIN_HEAD_PITCH, MAX_HEAD_PITCH) == (2.08, -0.67, 0.51)


def test_clamp_walk_keeps_direction():
    assert clampWalk(100.0, 50.0) == (100.0, 50.0)
    assert clampWalk(600.0, 100.0) == pytest.approx((300.0, 50.0))   # forward limit
    assert clampWalk(-500.0, 100.0) == pytest.approx((-200.0, 40.0))  # backward limit
    assert clampWalk(100.0, -400.0) == pytest.approx((50.0, -200.0))  # sideways limit


def test_clamp_turn():
    assert clampTurn(2.0) == 1.5
    assert clampTurn(-2.0) == -1.5
    assert clampTurn(0.25) == 0.25


def test_visible_range_is_the_thesis_formula():
    assert camera.visibleRange(MAX_HEAD_PITCH) == pytest.approx(1000.0)  # fully down
    assert camera.visibleRange(MIN_HEAD_PITCH) == pytest.approx(4000.0)  # fully up
    assert camera.visibleRange(-0.08) == pytest.approx(2500.0)


@pytest.mark.parametrize("distance, pitch", [(1000.0, 0.313333), (2500.0, -0.276667)])
def test_pitch_to_see_inverts_the_formula_with_a_margin(distance, pitch):
    assert camera.pitchToSee(distance) == pytest.approx(pitch, abs=1e-5)
    assert camera.visibleRange(camera.pitchToSee(distance)) == pytest.approx(distance + camera.CAMERA_RANGE_MARGIN)


def test_pitch_to_see_clamps_to_the_joint_limits():
    assert camera.pitchToSee(4000.0) == MIN_HEAD_PITCH
    assert camera.pitchToSee(0.0) == MAX_HEAD_PITCH
