"""A small team behaviour written for Touchline's tests against the rUNSWift behaviour API
(the `robot` module their framework imports): proof in CI that the runswift profile runs
such a folder, without their code.

tick(blackboard) is called once per camera frame and returns a robot.BehaviourRequest.
The body skill and the head skill are chosen by name (blackboard.behaviour.skill and
.headskill, robot_shim --param skill=... headskill=...), each a tree of tasks (task.py).
"""
import robot

from world import World
from skills.striker import Striker
from skills.stand_still import StandStill
from skills.supporter import Supporter
from head.scan import HeadScan
from head.fixed import HeadFixed

BODY_SKILLS = {"Striker": Striker, "Supporter": Supporter, "StandStill": StandStill}
HEAD_SKILLS = {"HeadScan": HeadScan, "HeadFixed": HeadFixed}

_world = None
_body = None
_head = None


def _make(skills, name, kind):
    if name not in skills:
        raise ImportError("no %s skill %r (have: %s)" % (kind, name, ", ".join(sorted(skills))))
    return skills[name](_world)


def tick(blackboard):
    global _world, _body, _head
    if _world is None:
        _world = World()
    _world.update(blackboard)
    if _body is None:
        _body = _make(BODY_SKILLS, blackboard.behaviour.skill, "body")
    if _head is None:
        _head = _make(HEAD_SKILLS, blackboard.behaviour.headskill, "head")

    request = robot.BehaviourRequest()
    request.actions = robot.All()
    _world.request = request
    _body.step()
    _head.step()

    # What the team hears: who plays the ball and where we are going.
    shared = request.behaviourSharedData
    shared.playingBall = _world.playing_ball
    shared.walkingToX = _world.walking_to[0]
    shared.walkingToY = _world.walking_to[1]
    shared.secondsSinceLastKick = _world.seconds_since_kick()
    # Chest green while the ball is seen, blue while it is lost.
    seen = _world.ball_seen()
    request.actions.leds.chestButton = robot.rgb(False, seen, not seen)
    request.behaviourDebugInfo.bodyBehaviourHierarchy = _world.trail
    _world.trail = ""
    return request
