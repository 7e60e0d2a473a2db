"""Unstick (issue #17: no robot stuck more than 10 s): turning on the spot for long becomes a
walk without turning, towards the ball, the team ball, the field's centre or the goalie's
home; the same hand-worked cases as tests/behaviour_cpp/skills/test_unstick.cpp."""
import actioncommand
import pytest
import robot
from boards import board, message

from skills.robot_limits import MAX_BACKWARD, MAX_FORWARD
from skills.team import Team
from skills.team_comm import ROLE_DEFENDER, ROLE_STRIKER, TeamInfo, encodeMessage
from skills.unstick import UNSTICK_MOVE_MM, UNSTICK_RECOVER_FRAMES, UNSTICK_TURN_RAD, UNSTICK_WINDOW_FRAMES, Unstick

WALK = robot.ActionType.WALK
FRAME_US = 33333


STUCK_FRAME = 59  # at 0.06 rad a frame the odometry has turned over UNSTICK_TURN_RAD (3.54 rad) on this tick


def spinBoard(frame, pos=(0.0, 0.0, 0.0), turnPerFrame=0.06, stepPerFrame=0.0, localised=True, **kwargs):
    """Frame `frame` of a robot whose odometry turns turnPerFrame rad and steps stepPerFrame mm
    forward (odometry x) every frame; localisation sees the steps along field x from pos, unless
    not `localised` (a walk against a robot: it stays at pos)."""
    pos = (pos[0] + stepPerFrame * frame * localised, pos[1], pos[2])
    return board(pos, utime=frame * FRAME_US, odometry=(stepPerFrame * frame, 0.0, turnPerFrame * frame), **kwargs)


def turning():
    return actioncommand.walk(turn=1.5)


def run(unstick, frames, target=None, **kwargs):
    """The bodies Unstick returns for `frames` frames of turning() requests."""
    return [unstick.tick(spinBoard(frame, **kwargs), turning(), target) for frame in range(frames)]


def runPath(unstick, path):
    """The bodies Unstick returns for turning() requests at the field origin (frame 0) and
    then along `path`, a (mm stepped forward, rad turned) pair per frame: odometry and
    localisation see the steps along field x (the test's odometry steps along its own x)."""
    bodies, x, theta = [], 0.0, 0.0
    for frame, (step, turn) in enumerate([(0.0, 0.0), *path]):
        x, theta = x + step, theta + turn
        blackboard = board((x, 0.0, 0.0), utime=frame * FRAME_US, odometry=(x, 0.0, theta))
        bodies.append(unstick.tick(blackboard, turning(), None))
    return bodies


def isRecovery(body):
    """The recovery walk with the ball 1000 mm ahead: straight at it, at full speed."""
    return (body.actionType, body.forward, body.left, body.turn) == (WALK, pytest.approx(MAX_FORWARD),
                                                                     pytest.approx(0.0), 0.0)


SPIN = [(0.0, 0.06)] * STUCK_FRAME  # 1.8 rad/s on the spot: over UNSTICK_TURN_RAD on its last tick


def test_turning_on_the_spot_becomes_a_walk_to_the_ball_without_turning_until_it_has_moved():
    walk = [(6.0, 0.0)] * (UNSTICK_RECOVER_FRAMES - 1)  # 354 mm
    bodies = runPath(Unstick(), [*SPIN, *walk, (0.0, 0.0)])
    assert all(b.turn == pytest.approx(1.5) for b in bodies[:STUCK_FRAME])
    assert all(isRecovery(b) for b in bodies[STUCK_FRAME:STUCK_FRAME + UNSTICK_RECOVER_FRAMES])
    assert bodies[-1].turn == pytest.approx(1.5)  # moved away from the turning: the request again


def test_a_blocked_recovery_goes_on_until_the_turning_has_left_the_window():
    bodies = runPath(Unstick(), [*SPIN, *[(0.0, 0.0)] * (UNSTICK_WINDOW_FRAMES + UNSTICK_RECOVER_FRAMES)])
    assert all(isRecovery(b) for b in bodies[STUCK_FRAME:UNSTICK_WINDOW_FRAMES])
    assert bodies[-1].turn == pytest.approx(1.5)


def test_a_walk_before_the_turning_does_not_hide_it():
    bodies = runPath(Unstick(), [*[(6.0, 0.0)] * 100, *SPIN])  # 600 mm, then the spin
    assert bodies[-2].turn == pytest.approx(1.5) and isRecovery(bodies[-1])


def test_the_window_and_limit_the_cases_rely_on():
    assert 0.06 * (STUCK_FRAME - 1) < UNSTICK_TURN_RAD < 0.06 * STUCK_FRAME
    assert 0.011 * (UNSTICK_WINDOW_FRAMES - 1) < UNSTICK_TURN_RAD
    assert 100 + STUCK_FRAME < UNSTICK_WINDOW_FRAMES  # the walk before the spin is in the window
    assert 6.0 * (UNSTICK_RECOVER_FRAMES - 1) > UNSTICK_MOVE_MM


def test_walking_or_turning_slowly_is_not_stuck():
    assert all(b.turn == pytest.approx(1.5) for b in run(Unstick(), 400, stepPerFrame=6.0))  # 354 mm in 59 frames
    assert all(b.turn == pytest.approx(1.5) for b in run(Unstick(), 400, turnPerFrame=0.011))  # 3.3 rad in 10 s


def test_a_walk_that_steps_on_in_odometry_only_is_stuck():
    bodies = run(Unstick(), STUCK_FRAME + 1, stepPerFrame=6.0, localised=False)
    assert bodies[STUCK_FRAME - 1].turn == pytest.approx(1.5) and bodies[STUCK_FRAME].turn == 0.0


def test_without_the_own_ball_it_walks_to_the_team_ball_else_the_centre_and_the_goalie_home():
    lost = dict(seen=False, lost=1000)
    assert run(Unstick(), STUCK_FRAME + 1, pos=(500.0, 0.0, 0.0), **lost)[-1].forward == pytest.approx(
        -MAX_BACKWARD)  # no ball known: back to the centre, 500 mm behind
    info = TeamInfo(3, ROLE_DEFENDER, True, False, False, 500, 0, 400)
    teamBall = dict(messages=[message(3, encodeMessage(info), STUCK_FRAME * FRAME_US)], **lost)
    body = run(Unstick(), STUCK_FRAME + 1, **teamBall)[-1]  # the team ball 400 mm to the left
    assert (body.forward, body.left, body.turn) == (pytest.approx(0.0, abs=1e-3), pytest.approx(200.0), 0.0)
    body = run(Unstick(), STUCK_FRAME + 1, target=(-2700.0, 0.0), pos=(-2000.0, 0.0, 0.0), player=1)[-1]
    assert (body.forward, body.left, body.turn) == (pytest.approx(-MAX_BACKWARD), pytest.approx(0.0, abs=1e-3), 0.0)


def test_the_team_unsticks_in_play_only_and_starts_afresh_after_a_penalty():
    team = Team(ROLE_STRIKER)
    frames = STUCK_FRAME - 1
    ball = (0.0, 1000.0)  # to the left: the striker turns on the spot to face the goal, the odometry spins
    for frame in range(frames):
        team.tick(spinBoard(frame, ball=ball))
    team.tick(spinBoard(frames, ball=ball, penalised=True))
    for frame in range(frames + 1, frames + 1 + STUCK_FRAME):  # the window starts again
        assert team.tick(spinBoard(frame, ball=ball)).body.turn < 0.0
    body = team.tick(spinBoard(frames + 1 + STUCK_FRAME, ball=ball)).body
    assert (body.turn, body.left) == (0.0, pytest.approx(200.0))  # stuck in play: sideways to the ball
