"""Team: the whole robot for a match. Game states, team messages, roles.

Every tick the head runs LandmarkGlance (LookForBall with glances at landmarks), or in PLAYING
looks where a ball lies that the referee put back and this field player has not seen since
(search.py's drop-in); every MESSAGE_EVERY_FRAMES frames (counted by its own ticks, never wall
time), the request carries this robot's team message. The body:
penalised or fallen: stand (it gets up by itself); INITIAL, STANDBY, SET, FINISHED: stand; READY: walk
to the player number's kick-off position (a fixed legal formation in the own half, outside
the centre circle, but for player 2 when its team kicks off: the ball is then before its
foot, and the kick-off is kicked as PLAYING begins, where from outside the circle the ball
lay still for the first 3.5 s); PLAYING: the role's skill,
roles assigned from the team messages (team_comm.assignRole) unless fixed. A field player
that has not seen the ball for SEARCH_TURN_FRAMES searches (search.py: the team ball, else a
short turn on the spot and a walk to a search spot, in cycles).
"""
import math

import actioncommand
import robot

from .ball import ballRecentlySeen
from .goalie import GOALIE_HOME_X, Goalie
from .go_to_pose import GoToPose
from .landmark_glance import LandmarkGlance
from .search import Search
from .striker import Striker
from .supporter import TUNED, Defender, Midfielder
from .track_ball import lookAt
from .unstick import Unstick
from .team_comm import (GOALIE_PLAYER, MESSAGE_EVERY_FRAMES, NO_BALL_DISTANCE, ROLE_DEFENDER, ROLE_GOALIE,
                        ROLE_MIDFIELDER, ROLE_NONE, ROLE_STRIKER, assignRole, encodeMessage, makeTeamInfo, roundMm)

TEAM_BALL_SEEN_CHEST = 0x00ff00  # green: the ball was seen recently
TEAM_BALL_LOST_CHEST = 0xff0000  # red: searching
READY_GOALIE_X = GOALIE_HOME_X   # mm: the kick-off formation (player 1 ...
READY_GOALIE_Y = 0.0
READY_STRIKER_X = -700.0         # mm: ... player 2, outside the 600 mm centre circle ...
READY_STRIKER_Y = 0.0
READY_KICKER_X = -150.0          # mm: ... or, when its team kicks off, inside it with the ball
READY_KICKER_Y = -50.0           # mm: (the centre mark) before its left foot, to kick at once ...
READY_DEFENDER_X = -1800.0       # mm: ... player 3 ...
READY_DEFENDER_Y = -600.0
READY_MIDFIELDER_X = -1200.0     # mm: ... player 4; players 5 on: 3 and 4 mirrored in y)
READY_MIDFIELDER_Y = 900.0


def formationRole(playerNumber):
    """The role whose kick-off position a player takes: 1 goalie, 2 striker, 3 defender,
    4 midfielder, then defender and midfielder alternately."""
    if playerNumber == GOALIE_PLAYER:
        return ROLE_GOALIE
    if playerNumber == 2:
        return ROLE_STRIKER
    return ROLE_DEFENDER if playerNumber % 2 == 1 else ROLE_MIDFIELDER


def readyPosition(playerNumber, kickingOff=False):
    """(x, y) of the player's kick-off position, team frame, facing +x; kickingOff: its team
    kicks off."""
    role = formationRole(playerNumber)
    if role == ROLE_GOALIE:
        return READY_GOALIE_X, READY_GOALIE_Y
    if role == ROLE_STRIKER:
        return (READY_KICKER_X, READY_KICKER_Y) if kickingOff else (READY_STRIKER_X, READY_STRIKER_Y)
    mirror = -1.0 if playerNumber >= 5 else 1.0
    if role == ROLE_DEFENDER:
        return READY_DEFENDER_X, mirror * READY_DEFENDER_Y
    return READY_MIDFIELDER_X, mirror * READY_MIDFIELDER_Y


def messageInfo(blackboard, role):
    """This robot's TeamInfo from its Blackboard."""
    gc = blackboard.gameController
    ball = blackboard.localisation.ballPos
    pos = blackboard.localisation.robotPos
    return makeTeamInfo(gc.playerNumber, role, ballRecentlySeen(blackboard), gc.penalised, blackboard.motion.fallen,
                        blackboard.localisation.ballPosRR.distance, ball.x, ball.y, pos.x, pos.y)


def messageBallDistance(blackboard):
    """messageInfo(blackboard, role).ballDistance without the rest of the message (the role
    needs only this, every tick). Where messageInfo would raise (a position that is not
    finite: math.floor) it is called, and raises the same."""
    localisation = blackboard.localisation
    ball = localisation.ballPos
    pos = localisation.robotPos
    isfinite = math.isfinite
    if not (isfinite(ball.x) and isfinite(ball.y) and isfinite(pos.x) and isfinite(pos.y)):
        return messageInfo(blackboard, ROLE_NONE).ballDistance
    if ballRecentlySeen(blackboard):
        return roundMm(localisation.ballPosRR.distance, 0, NO_BALL_DISTANCE - 1)
    return NO_BALL_DISTANCE


class Team:
    def __init__(self, fixedRole=ROLE_NONE, policy=None, supporters=TUNED):
        """fixedRole: play this role always (ROLE_NONE: assign roles from the messages);
        policy: the striker's learned walker policy file (None: GoToPose); supporters: the
        SupporterDef the midfielder and defender play (supporter.py: TUNED or THESIS)."""
        self.fixedRole = fixedRole
        self.role = fixedRole
        self.skills = {ROLE_GOALIE: Goalie(), ROLE_STRIKER: Striker(policy), ROLE_DEFENDER: Defender(supporters),
                       ROLE_MIDFIELDER: Midfielder(supporters)}
        self.readyPose = GoToPose()
        self.head = LandmarkGlance()
        self.search = Search(supporters)
        self.unstick = Unstick()
        self.frame = 0

    def tick(self, blackboard):
        self.role = self.chooseRole(blackboard)
        body = self.body(blackboard)
        # A ball put back unseen is looked for where it was put; else LandmarkGlance.
        dropIn = self.search.dropIn
        playing = blackboard.gameController.state == robot.GameState.PLAYING
        if dropIn is not None and self.role != ROLE_GOALIE and playing:
            head = lookAt(robot.toRobotRelative(blackboard.localisation.robotPos, *dropIn))
        else:
            head = self.head.tick(blackboard).head
        chest = TEAM_BALL_SEEN_CHEST if ballRecentlySeen(blackboard) else TEAM_BALL_LOST_CHEST
        command = actioncommand.compose(head=head, body=body, leds=actioncommand.leds(chest))
        if self.frame % MESSAGE_EVERY_FRAMES == 0:
            command.teamMessage = encodeMessage(messageInfo(blackboard, self.role))
        self.frame += 1
        return command

    def chooseRole(self, blackboard):
        if self.fixedRole != ROLE_NONE:
            return self.fixedRole
        return assignRole(blackboard.gameController.playerNumber, messageBallDistance(blackboard), self.role,
                          blackboard.receiver.messages, blackboard.utime)

    def body(self, blackboard):
        gc = blackboard.gameController
        playing = gc.state == robot.GameState.PLAYING and not gc.penalised and not blackboard.motion.fallen
        if not playing:
            self.unstick.reset()  # stuck counts in play only
        if gc.penalised or blackboard.motion.fallen:
            return actioncommand.stand()
        if gc.state == robot.GameState.READY:
            x, y = readyPosition(gc.playerNumber, gc.kickOffTeam == gc.team)
            self.readyPose.setTarget(x, y, 0.0)
            return self.readyPose.tick(blackboard).body
        if gc.state != robot.GameState.PLAYING:
            return actioncommand.stand()
        # Every role's body goes through Unstick: turning on the spot for long, whatever the
        # cause, becomes a walk without turning (issue #17); the goalie's towards its home.
        home = (GOALIE_HOME_X, 0.0) if self.role == ROLE_GOALIE else None
        return self.unstick.tick(blackboard, self.playBody(blackboard), home)

    def playBody(self, blackboard):
        if self.role != ROLE_GOALIE:
            body = self.search.tick(blackboard, self.role)
            if body is not None:
                return body
        return self.skills[self.role].tick(blackboard).body
