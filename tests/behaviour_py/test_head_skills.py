"""TrackBall, HeadScan and LookForBall; the same cases as
tests/behaviour_cpp/skills/test_head_skills.cpp."""
import math

import pytest
import robot
from boards import board, relative

from skills.ball import BALL_LOST_FRAMES
from skills.camera import visibleRange
from skills.head_scan import SCAN_PITCH, SCAN_STEPS, SCAN_YAW_STEP, HeadScan
from skills.look_for_ball import LookForBall
from skills.robot_limits import MAX_HEAD_PITCH, MAX_HEAD_YAW, MIN_HEAD_PITCH
from skills.track_ball import TrackBall

ORIGIN = (0.0, 0.0, 0.0)


def ball_at(distance, heading):
    return relative(ORIGIN, distance * math.cos(heading), distance * math.sin(heading))


@pytest.mark.parametrize("distance, pitch", [(1000.0, 0.313333), (2500.0, -0.276667)])
def test_track_ball_points_at_the_ball_with_the_pitch_that_sees_it(distance, pitch):
    head = TrackBall().tick(board(ORIGIN, ball=ball_at(distance, 0.5))).head
    assert head.yaw == pytest.approx(0.5, abs=1e-5)
    assert head.pitch == pytest.approx(pitch, abs=1e-5)
    assert visibleRange(head.pitch) > distance


def test_track_ball_clamps_to_the_joint_limits():
    head = TrackBall().tick(board(ORIGIN, ball=ball_at(4000.0, 2.5))).head
    assert (head.yaw, head.pitch) == pytest.approx((MAX_HEAD_YAW, MIN_HEAD_PITCH))  # far: look up
    head = TrackBall().tick(board(ORIGIN, ball=ball_at(100.0, -2.5))).head
    assert (head.yaw, head.pitch) == pytest.approx((-MAX_HEAD_YAW, MAX_HEAD_PITCH))  # near: look down


def test_track_ball_uses_localisation_when_vision_missed_it():
    blackboard = board(ORIGIN, ball=ball_at(1000.0, 0.5), seen=False, lost=3)
    blackboard.vision.ball = robot.RRCoord(3000.0, -1.0)  # stale: ignored
    head = TrackBall().tick(blackboard).head
    assert (head.yaw, head.pitch) == pytest.approx((0.5, 0.313333), abs=1e-5)


def scan_yaws(scan, blackboard, ticks):
    return [scan.tick(blackboard).head.yaw for _ in range(ticks)]


def test_head_scan_sweeps_within_the_joint_limits_and_reverses():
    scan = HeadScan()
    blackboard = board(ORIGIN, ball=ball_at(1000.0, 0.1), lost=100)
    yaws = scan_yaws(scan, blackboard, 200)
    assert yaws[0] == pytest.approx(SCAN_YAW_STEP)                 # towards the ball's side first
    assert yaws[SCAN_STEPS - 1] == pytest.approx(MAX_HEAD_YAW)     # left limit after 40 frames
    assert yaws[SCAN_STEPS] == pytest.approx(MAX_HEAD_YAW - SCAN_YAW_STEP)  # reversed
    assert yaws[3 * SCAN_STEPS - 1] == pytest.approx(-MAX_HEAD_YAW)  # right limit
    assert yaws[3 * SCAN_STEPS] == pytest.approx(-MAX_HEAD_YAW + SCAN_YAW_STEP)
    assert all(abs(yaw) <= MAX_HEAD_YAW + 1e-6 for yaw in yaws)
    steps = [b - a for a, b in zip(yaws, yaws[1:])]
    assert all(abs(abs(step) - SCAN_YAW_STEP) < 1e-5 for step in steps)  # a steady pace
    assert scan.tick(blackboard).head.pitch == pytest.approx(SCAN_PITCH)
    assert SCAN_PITCH == pytest.approx(-0.08)


def test_head_scan_starts_towards_the_ball_side_from_the_head_yaw():
    assert HeadScan().tick(board(ORIGIN, ball=ball_at(1000.0, -0.1), lost=100)).head.yaw == pytest.approx(-SCAN_YAW_STEP)
    yaw = HeadScan().tick(board(ORIGIN, ball=ball_at(1000.0, 0.1), lost=100, headYaw=1.0)).head.yaw
    assert yaw == pytest.approx(20 * SCAN_YAW_STEP)  # from step round(1.0 / 0.052) = 19


def test_head_scan_from_the_limit_turns_back():
    scan = HeadScan()
    blackboard = board(ORIGIN, ball=ball_at(1000.0, 0.1), lost=100, headYaw=MAX_HEAD_YAW)
    assert scan_yaws(scan, blackboard, 2) == pytest.approx([MAX_HEAD_YAW, MAX_HEAD_YAW - SCAN_YAW_STEP])


def test_head_scan_is_deterministic():
    blackboard = board(ORIGIN, ball=ball_at(1000.0, 0.1), lost=100, headYaw=0.3)
    assert scan_yaws(HeadScan(), blackboard, 100) == scan_yaws(HeadScan(), blackboard, 100)


def test_look_for_ball_tracks_then_scans_then_restarts_the_scan():
    skill = LookForBall()
    seen = board(ORIGIN, ball=ball_at(1000.0, 0.5))
    lost = board(ORIGIN, ball=ball_at(1000.0, 0.5), seen=False, lost=BALL_LOST_FRAMES + 1)
    assert skill.tick(seen).head.yaw == pytest.approx(0.5, abs=1e-5)
    assert scan_yaws(skill, lost, 3) == pytest.approx([SCAN_YAW_STEP, 2 * SCAN_YAW_STEP, 3 * SCAN_YAW_STEP])
    skill.tick(seen)
    assert skill.tick(lost).head.yaw == pytest.approx(SCAN_YAW_STEP)  # a fresh scan
