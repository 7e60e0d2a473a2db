"""The robot's behaviour: tick(blackboard) -> robot.All, once per camera frame.

robot.params (strings, set by the shim) picks the body skill with "skill" (default
GoToBall) and gives its parameters ("Team" plays a match: roles from team messages;
"Goalie", "Striker", "Midfielder", "Defender" play that one role in a match; these take
"supporters=tuned" (the default) or "supporters=thesis", the numbers the midfielder and defender
play, skills/supporter.py's SupporterDef; "walker=learned"
makes the skills that walk to the ball use the learned policy "policy", data-relative,
default policies/go_to_pose.policy); the head runs LookForBall (TrackBall while the ball was
seen recently, else HeadScan); the chest LED says whether the ball is seen. The C++ port is
behaviour_cpp/src/registry.cpp (same skill names and parameters) and skills/skill_behaviour.
"""
import math

import actioncommand
import robot

from skills.ball import BEHIND_BALL_DIST, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, ballRecentlySeen
from skills.go_to_ball import GoToBall
from skills.go_to_pose import GoToPose
from skills.head_scan import HeadScan
from skills.learned_go_to_pose import LearnedGoToPose
from skills.line_up_and_kick import DRIBBLE_POWER, KICK_POWER, LineUpAndKick
from skills.look_for_ball import LookForBall
from skills.stand import Stand
from skills.team import Team
from skills.supporter import SUPPORTER_DEFS
from skills.team_comm import ROLE_DEFENDER, ROLE_GOALIE, ROLE_MIDFIELDER, ROLE_NONE, ROLE_STRIKER
from skills.tile_policy import DEFAULT_POLICY
from skills.track_ball import TrackBall

DEFAULT_SKILL = "GoToBall"
BALL_SEEN_CHEST = 0x00ff00   # green: the ball was seen recently
BALL_LOST_CHEST = 0xff0000   # red: searching
WALKER_HAND = "hand"         # walker=hand: GoToPose walks to the ball (the default)
WALKER_LEARNED = "learned"   # walker=learned: LearnedGoToPose with the policy file "policy"


class BehaviourError(ValueError):
    """A wrong skill name or parameter; the message is one line for the user."""


class SkillBehaviour:
    """A body skill and a head skill ticked together, with the chest LED."""

    def __init__(self, body, head):
        self.body = body
        self.head = head

    def tick(self, blackboard):
        body = self.body.tick(blackboard).body
        head = self.head.tick(blackboard).head
        chest = BALL_SEEN_CHEST if ballRecentlySeen(blackboard) else BALL_LOST_CHEST
        return actioncommand.compose(head=head, body=body, leds=actioncommand.leds(chest))


class ParamReader:
    """Reads numeric skill parameters, rejecting unknown keys and malformed numbers (as the
    C++ registry's ParamReader does)."""

    def __init__(self, skill, params):
        self.skill = skill
        self.params = params
        self.known = {"skill"}

    def number(self, key, fallback):
        self.known.add(key)
        if key not in self.params:
            return fallback
        text = self.params[key]
        try:
            # As strtof: leading spaces pass, trailing ones and underscores do not.
            value = float(text) if text.rstrip() == text and "_" not in text else math.nan
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            raise BehaviourError("%s: parameter %s must be a number (got '%s')" % (self.skill, key, text))
        return value

    def flag(self, key):
        return self.number(key, 0.0) != 0.0

    def text(self, key, fallback):
        self.known.add(key)
        return self.params.get(key, fallback)

    def supporters(self):
        """The SupporterDef the team's midfielder and defender play: supporters=tuned (the
        default) or thesis (Algorithms 4.1 and 4.2 with the thesis's numbers)."""
        name = self.text("supporters", next(iter(SUPPORTER_DEFS)))
        if name not in SUPPORTER_DEFS:
            raise BehaviourError("%s: parameter supporters must be %s (got '%s')"
                                 % (self.skill, " or ".join(SUPPORTER_DEFS), name))
        return SUPPORTER_DEFS[name]

    def walker(self):
        """The policy file the learned walker uses (walker=learned; policy=..., data-relative),
        or None for GoToPose (walker=hand, the default)."""
        walker = self.text("walker", WALKER_HAND)
        if walker not in (WALKER_HAND, WALKER_LEARNED):
            raise BehaviourError("%s: parameter walker must be %s or %s (got '%s')"
                                 % (self.skill, WALKER_HAND, WALKER_LEARNED, walker))
        policy = self.text("policy", None)
        if walker == WALKER_HAND:
            if policy is not None:
                raise BehaviourError("%s: parameter policy needs walker=%s" % (self.skill, WALKER_LEARNED))
            return None
        return DEFAULT_POLICY if policy is None else policy

    def rejectUnknown(self):
        for key in sorted(self.params):
            if key not in self.known:
                raise BehaviourError("%s: unknown parameter '%s'" % (self.skill, key))


def makeGoToPose(p):
    return GoToPose(p.number("x", 0.0), p.number("y", 0.0), p.number("theta", 0.0), p.flag("face_ball"))


def makeLearnedGoToPose(p):
    return LearnedGoToPose(p.number("x", 0.0), p.number("y", 0.0), p.number("theta", 0.0),
                           p.text("policy", DEFAULT_POLICY))


def makeGoToBall(p):
    goalX = p.number("goal_x", OPPONENT_GOAL_X)
    goalY = p.number("goal_y", OPPONENT_GOAL_Y)
    return GoToBall(goalX, goalY, p.number("behind", BEHIND_BALL_DIST), p.walker())


def makeLineUpAndKick(p):
    goalX = p.number("goal_x", OPPONENT_GOAL_X)
    goalY = p.number("goal_y", OPPONENT_GOAL_Y)
    dribble = p.flag("dribble")
    power = p.number("power", DRIBBLE_POWER if dribble else KICK_POWER)
    return LineUpAndKick(goalX, goalY, dribble, power, p.walker())


# Skill name -> (body skill factory, head skill factory); a head factory None: the body
# factory makes the whole behaviour (the team and its roles: head, LEDs, messages, game
# states). Names match the C++ registry.
SKILL_NAMES = ("GoToPose", "LearnedGoToPose", "GoToBall", "LineUpAndKick", "TrackBall", "HeadScan", "Team", "Goalie",
               "Striker", "Midfielder", "Defender")
SKILLS = {
    "GoToPose": (makeGoToPose, LookForBall),
    "LearnedGoToPose": (makeLearnedGoToPose, LookForBall),
    "GoToBall": (makeGoToBall, LookForBall),
    "LineUpAndKick": (makeLineUpAndKick, LookForBall),
    "TrackBall": (lambda p: Stand(), TrackBall),
    "HeadScan": (lambda p: Stand(), HeadScan),
    "Team": (lambda p: Team(ROLE_NONE, p.walker(), p.supporters()), None),
    "Goalie": (lambda p: Team(ROLE_GOALIE, p.walker(), p.supporters()), None),
    "Striker": (lambda p: Team(ROLE_STRIKER, p.walker(), p.supporters()), None),
    "Midfielder": (lambda p: Team(ROLE_MIDFIELDER, p.walker(), p.supporters()), None),
    "Defender": (lambda p: Team(ROLE_DEFENDER, p.walker(), p.supporters()), None),
}


def makeBehaviour(params):
    """The SkillBehaviour that params (a dict of strings) asks for. Raises BehaviourError."""
    name = params.get("skill", DEFAULT_SKILL)
    if name not in SKILLS:
        raise BehaviourError("unknown skill '%s' (known: %s)" % (name, ", ".join(SKILL_NAMES)))
    makeBody, makeHead = SKILLS[name]
    reader = ParamReader(name, params)
    body = makeBody(reader)
    reader.rejectUnknown()
    if makeHead is None:
        return body
    return SkillBehaviour(body, makeHead())


def check_params(params):
    """Raises BehaviourError (one line) when params ask for a skill or parameter that does not
    exist; the shim calls it before the match, so a typo stops the start instead of leaving the
    robot standing."""
    makeBehaviour(dict(params))


_behaviour = None
_params = None


def reset():
    """Forget the running skill: the next tick builds it afresh from robot.params."""
    global _behaviour, _params
    _behaviour = None
    _params = None


def tick(blackboard):
    global _behaviour, _params
    params = dict(getattr(robot, "params", {}))
    if _behaviour is None or params != _params:  # one skill instance while params stay
        _behaviour = makeBehaviour(params)
        _params = params
    return _behaviour.tick(blackboard)
