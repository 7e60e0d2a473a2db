"""LandmarkGlance: glances at a landmark now and then, sooner when the pose is unsure, never
with the ball hot; the same cases as tests/behaviour_cpp/skills/test_landmark_glance.cpp."""
import math

import pytest
import robot
from boards import board

from skills.ball import BALL_LOST_FRAMES
from skills.camera import pitchToSee
from skills.head_scan import SCAN_YAW_STEP
from skills.look_for_ball import LookForBall
from skills.landmark_glance import (GLANCE_DWELL_FRAMES, GLANCE_EVERY_FRAMES, GLANCE_HOT_BALL_DIST,
                                    GLANCE_LOST_SIGMA_MM, GLANCE_MAX_DIST, GLANCE_MAX_FRAMES, GLANCE_SIGMA_MM,
                                    GLANCE_SIGMA_RAD, GLANCE_UNSURE_EVERY_FRAMES, LandmarkGlance, glanceTarget,
                                    landmarks, poseLost, poseUnsure)

CENTRE = (0.0, 0.0, 0.0)
POST_YAW = math.atan2(700.0, 3000.0)  # team 1's left post (3000, 700) from the centre spot


def ball_at(distance, heading, **kwargs):
    return board(CENTRE, ball=(distance * math.cos(heading), distance * math.sin(heading)), **kwargs)


def covariance(sigma_mm=0.0, sigma_rad=0.0):
    """Position sigma sigma_mm (x and y together: half the variance on each), heading sigma_rad."""
    half = sigma_mm * sigma_mm / 2
    return [half, 0.0, 0.0, 0.0, half, 0.0, 0.0, 0.0, sigma_rad * sigma_rad]


def with_covariance(blackboard, sigma_mm=0.0, sigma_rad=0.0):
    blackboard.localisation.robotPosCovariance = covariance(sigma_mm, sigma_rad)
    return blackboard


def yaws(skill, blackboard, ticks):
    return [skill.tick(blackboard).head.yaw for _ in range(ticks)]


def test_the_landmarks_are_the_twelve_the_camera_reports_and_symmetric():
    points = landmarks()
    assert len(points) == 12
    assert sorted(points) == sorted((-x, -y) for x, y in points)  # the same for both teams
    assert (3000.0, 700.0) in points and (1200.0, 0.0) in points and (0.0, -2000.0) in points


def test_the_target_is_the_landmark_in_range_nearest_the_ball_bearing():
    target = glanceTarget(robot.AbsCoord(*CENTRE), 0.0)
    assert (target.distance, target.heading) == pytest.approx((1200.0, 0.0), abs=1e-3)  # the penalty mark ahead
    target = glanceTarget(robot.AbsCoord(*CENTRE), 0.5)
    assert target.heading == pytest.approx(POST_YAW, abs=1e-6)
    target = glanceTarget(robot.AbsCoord(*CENTRE), 1.4)
    assert (target.distance, target.heading) == pytest.approx((2000.0, math.pi / 2), abs=1e-3)  # centre-line end
    # Corners 3606 mm away are out of range, and so is everything behind the head's reach.
    assert math.hypot(3000.0, 2000.0) > GLANCE_MAX_DIST
    target = glanceTarget(robot.AbsCoord(*CENTRE), -3.0)
    assert target.heading == pytest.approx(-math.pi / 2, abs=1e-6)


def test_a_landmark_underfoot_is_no_target():
    target = glanceTarget(robot.AbsCoord(1200.0, 0.0, 0.0), 0.1)  # on the penalty mark
    assert target.heading == pytest.approx(math.atan2(700.0, 1800.0), abs=1e-6)


def test_the_pose_is_unsure_past_either_sigma():
    sure = with_covariance(ball_at(1000.0, 0.0), 0.9 * GLANCE_SIGMA_MM, 0.9 * GLANCE_SIGMA_RAD)
    assert not poseUnsure(sure.localisation)
    assert poseUnsure(with_covariance(ball_at(1000.0, 0.0), 1.1 * GLANCE_SIGMA_MM).localisation)
    assert poseUnsure(with_covariance(ball_at(1000.0, 0.0), 0.0, 1.1 * GLANCE_SIGMA_RAD).localisation)


def test_a_sure_robot_glances_every_few_seconds_and_returns_to_the_ball():
    skill = LandmarkGlance()
    blackboard = with_covariance(ball_at(1000.0, 0.5))
    before = yaws(skill, blackboard, GLANCE_EVERY_FRAMES - 1)
    assert before == pytest.approx([0.5] * (GLANCE_EVERY_FRAMES - 1), abs=1e-5)  # on the ball
    head = skill.tick(blackboard).head
    assert (head.yaw, head.pitch) == pytest.approx((POST_YAW, pitchToSee(math.hypot(3000.0, 700.0))), abs=1e-5)
    # The head never gets there on this board: the glance gives up after GLANCE_MAX_FRAMES.
    glance = yaws(skill, blackboard, GLANCE_MAX_FRAMES - 1)
    assert glance == pytest.approx([POST_YAW] * (GLANCE_MAX_FRAMES - 1), abs=1e-6)
    assert GLANCE_MAX_FRAMES < BALL_LOST_FRAMES  # the ball is not yet lost when it ends
    after = yaws(skill, blackboard, GLANCE_EVERY_FRAMES)
    assert after[:-1] == pytest.approx([0.5] * (GLANCE_EVERY_FRAMES - 1), abs=1e-5)
    assert after[-1] == pytest.approx(POST_YAW, abs=1e-6)  # the next glance


def test_a_glance_ends_after_the_dwell_once_the_head_is_on_the_landmark():
    skill = LandmarkGlance()
    yaws(skill, with_covariance(ball_at(1000.0, 0.5)), GLANCE_EVERY_FRAMES)  # the glance starts
    there = with_covariance(ball_at(1000.0, 0.5, headYaw=POST_YAW + 0.05))
    glance = yaws(skill, there, GLANCE_DWELL_FRAMES + 1)
    assert glance[:GLANCE_DWELL_FRAMES] == pytest.approx([POST_YAW] * GLANCE_DWELL_FRAMES, abs=1e-6)
    assert glance[-1] == pytest.approx(0.5, abs=1e-5)


def test_an_unsure_robot_glances_sooner():
    skill = LandmarkGlance()
    blackboard = with_covariance(ball_at(1000.0, 0.5), 1.1 * GLANCE_SIGMA_MM)
    seen = yaws(skill, blackboard, GLANCE_UNSURE_EVERY_FRAMES)
    assert seen[:-1] == pytest.approx([0.5] * (GLANCE_UNSURE_EVERY_FRAMES - 1), abs=1e-5)
    assert seen[-1] == pytest.approx(POST_YAW, abs=1e-6)


def test_a_hot_ball_keeps_the_head_and_ends_a_glance():
    skill = LandmarkGlance()
    hot = with_covariance(ball_at(0.9 * GLANCE_HOT_BALL_DIST, 0.5), 1.1 * GLANCE_SIGMA_MM)
    assert yaws(skill, hot, 3 * GLANCE_EVERY_FRAMES) == pytest.approx([0.5] * (3 * GLANCE_EVERY_FRAMES), abs=1e-5)
    skill = LandmarkGlance()
    assert yaws(skill, with_covariance(ball_at(1000.0, 0.5)), GLANCE_EVERY_FRAMES)[-1] == pytest.approx(POST_YAW)
    assert skill.tick(hot).head.yaw == pytest.approx(0.5, abs=1e-5)


def test_the_pose_is_lost_past_its_position_sigma_only():
    assert not poseLost(with_covariance(ball_at(1000.0, 0.0), 0.9 * GLANCE_LOST_SIGMA_MM, 3.0).localisation)
    assert poseLost(with_covariance(ball_at(1000.0, 0.0), 1.1 * GLANCE_LOST_SIGMA_MM).localisation)


def test_a_lost_robot_glances_even_with_the_ball_hot():
    # Toe to toe over the ball, a blocked walk's odometry runs the pose off: only a landmark
    # brings it back.
    skill = LandmarkGlance()
    hot = with_covariance(ball_at(0.9 * GLANCE_HOT_BALL_DIST, 0.5), 1.1 * GLANCE_LOST_SIGMA_MM)
    seen = yaws(skill, hot, GLANCE_UNSURE_EVERY_FRAMES + GLANCE_MAX_FRAMES - 1)
    assert seen[:GLANCE_UNSURE_EVERY_FRAMES - 1] == pytest.approx([0.5] * (GLANCE_UNSURE_EVERY_FRAMES - 1), abs=1e-5)
    assert seen[GLANCE_UNSURE_EVERY_FRAMES - 1:] == pytest.approx([POST_YAW] * GLANCE_MAX_FRAMES, abs=1e-6)


def test_a_lost_ball_is_searched_for_not_glanced_away_from():
    skill = LandmarkGlance()
    lost = with_covariance(ball_at(1000.0, 0.5, seen=False, lost=BALL_LOST_FRAMES + 1), 1.1 * GLANCE_SIGMA_MM)
    scan = yaws(skill, lost, 2 * GLANCE_EVERY_FRAMES)
    assert scan[:3] == pytest.approx([SCAN_YAW_STEP, 2 * SCAN_YAW_STEP, 3 * SCAN_YAW_STEP], abs=1e-5)
    assert scan == yaws(LookForBall(), lost, 2 * GLANCE_EVERY_FRAMES)  # LookForBall's scan, no glance
