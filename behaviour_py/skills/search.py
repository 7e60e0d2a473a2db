"""Search: the body of a field player (not the goalie) that has not seen the ball for
SEARCH_TURN_FRAMES, so that a lost robot never turns on the spot for long (issue #17; the
thesis saw supporters spinning when lost), or has not seen it since the referee put it back
after it left the field. Reads the Blackboard's localisation, gameController, receiver and
motion (its touches, through avoid's keepClear and GoToPose's Avoid); writes nothing.

  drop-in:    the GameController's dropInTime started again (SPL 2011: a ball that left the
              field was put back) while this robot did not see the ball, at most
              DROP_IN_FRESH_S ago, and it has not seen the ball since: walk to where the role
              stands for the ball where the rules put it (dropInSpot, from the robot's last
              sighting; Team points the head there too). Without it a robot looked where the
              ball left, often facing away from where it lay: in C++ matches (cpp:Team v
              cpp:Striker, seeds 1-4) the referee put the ball back 79 times a match, and it
              lay there 4.9 s (median) before it moved.
  team ball:  a teammate saw the ball recently (its message says so, is at most
              MESSAGE_STALE_US old, and it is not penalised): walk to where the role stands
              for that ball (the striker behind it, a supporter at its algorithm's target),
              ending facing it. Of several, the nearest to its seer counts (ties: the lower
              player number).
  at feet:    its own last sighting puts the ball within BALL_AT_FEET_DIST of the body (a
              robot that walked onto the ball stands on it, where no head turn sees it):
              step straight away from it, without turning, until it would be that far.
  otherwise:  cycles of SEARCH_CYCLE_FRAMES: turn on the spot for SEARCH_TURN_LIMIT_FRAMES
              towards the side the ball was last seen on (under a full turn), then walk to
              the cycle's search spot (four round the centre circle in turn, each role
              starting at its own), the head scanning all the while. A supporter's first cycle is the thesis's:
              it walks home, and turns only there.
"""
import math

import actioncommand
import robot

from .avoid import keepClear
from .ball import BEHIND_BALL_DIST, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, kickAim, pointBehindBall
from .field import FIELD_HALF_LENGTH, FIELD_HALF_WIDTH, distance
from .goalie import GOALIE_HOME_X
from .go_to_pose import GoToPose
from .robot_limits import clamp
from .supporter import TUNED, defenderTarget, midfielderTarget, supporterTarget
from .team_comm import MESSAGE_STALE_US, ROLE_DEFENDER, ROLE_MIDFIELDER, ROLE_STRIKER, decodeMessage

SEARCH_TURN_FRAMES = 90          # frames (3 s) without the ball before searching
SEARCH_TURN_SPEED = 0.8          # rad/s
SEARCH_TURN_LIMIT_FRAMES = 150   # frames of turning (4 rad, well under a full turn) ...
SEARCH_CYCLE_FRAMES = 520        # ... of every cycle; the rest walks to a search spot
HOME_NEAR_DIST = 300.0           # mm: a supporter this close to home may turn to search
SEARCH_SPOT_X = 1500.0           # mm: the search spots are (X, 0), (0, Y), (-X, 0), (0, -Y), in turn ...
SEARCH_SPOT_Y = 1200.0           # mm: ... each 1.9 m from the next
SEARCH_SPOT_COUNT = 4
STRIKER_FIRST_SPOT = 0           # the striker searches the opponent half first, ...
MIDFIELDER_FIRST_SPOT = 1        # ... the midfielder its own side ...
DEFENDER_FIRST_SPOT = 2          # ... and the defender the own half
BALL_AT_FEET_DIST = 250.0        # mm: a lost ball last seen this near lies at the feet, so ...
SEARCH_BACK_OFF_SPEED = 150.0    # mm/s: ... the robot steps away from it this fast, not turning
DROP_IN_SETBACK = 1000.0         # mm: SPL 2011 puts a ball that left the field back this far towards
                                 # the goal of the team that put it out, ...
THROW_IN_LINE_INSET = 400.0      # mm: ... on the throw-in line, this far inside the touchline, ...
THROW_IN_LINE_END = 1000.0       # mm: ... which ends this far short of each goal line
DROP_IN_FRESH_S = 8              # s: a ball put back this recently is looked for where it was put


def homePosition(role, supporters):
    """(x, y) a role walks back to while the ball is lost; supporters: the SupporterDef played."""
    if role == ROLE_DEFENDER:
        return supporters.defHomeX, supporters.defHomeY
    if role == ROLE_MIDFIELDER:
        return supporters.midHomeX, supporters.midHomeY
    return GOALIE_HOME_X, 0.0


def teamBall(playerNumber, messages, utime):
    """(x, y) of the ball as the teammates see it, or None: the sighting of the teammate
    nearest to it among those whose message is fresh, says the ball was seen, and is not
    from a penalised robot."""
    best = None
    for message in messages:
        if message.playerNumber == playerNumber or utime - message.utime > MESSAGE_STALE_US:
            continue
        info = decodeMessage(message.data)
        if info is None or not info.ballSeen or info.penalised:
            continue
        key = (info.ballDistance, info.playerNumber)
        if best is None or key < best[0]:
            best = (key, info.ballX, info.ballY)
    return None if best is None else (float(best[1]), float(best[2]))


def teamBallTarget(role, ballX, ballY, robotY, supporters):
    """(x, y, theta): where the role stands for the ball at (ballX, ballY): the striker
    behind it facing the opponent goal (or along the line a ball on it lies on, as GoToBall
    stands: ball.py's kickAim), a supporter at its algorithm's target (the numbers of
    the SupporterDef `supporters`) facing it."""
    if role == ROLE_STRIKER:
        aimX, aimY = kickAim(ballX, ballY, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, BEHIND_BALL_DIST)
        return pointBehindBall(robot.AbsCoord(ballX, ballY, 0.0), aimX, aimY, BEHIND_BALL_DIST)
    if role == ROLE_DEFENDER:
        x, y = defenderTarget(ballX, ballY, supporters)
    else:
        x, y = midfielderTarget(ballX, ballY, robotY, supporters)
    x, y = supporterTarget(x, y, ballX, ballY, robotY)
    return x, y, math.atan2(ballY - y, ballX - x)


def searchSpot(role, walk):
    """(x, y) of the role's walk-th search spot (0: its first)."""
    first = {ROLE_STRIKER: STRIKER_FIRST_SPOT, ROLE_MIDFIELDER: MIDFIELDER_FIRST_SPOT}.get(role, DEFENDER_FIRST_SPOT)
    spot = (first + walk) % SEARCH_SPOT_COUNT
    sign = 1.0 if spot < 2 else -1.0
    return (sign * SEARCH_SPOT_X, 0.0) if spot % 2 == 0 else (0.0, sign * SEARCH_SPOT_Y)


def dropInSpot(ballX, ballY, dropInTeam, ourTeam):
    """(x, y) where the SPL 2011 rules put back a ball last seen at (ballX, ballY) that then
    left the field over the line it lies farther beyond (or nearer inside), by the team
    dropInTeam (ours, ourTeam, defends -x; -1: not known): on the throw-in line on its side.
    Over a touchline, DROP_IN_SETBACK along x towards dropInTeam's goal (not known: not
    moved), within the throw-in line's ends; over a goal line, at the halfway line if the
    goal's attackers put it out, else at the throw-in line's end by that goal line."""
    sideX = -1.0 if ballX < 0.0 else 1.0
    sideY = -1.0 if ballY < 0.0 else 1.0
    lineY = sideY * (FIELD_HALF_WIDTH - THROW_IN_LINE_INSET)
    lineEndX = FIELD_HALF_LENGTH - THROW_IN_LINE_END
    if abs(ballY) - FIELD_HALF_WIDTH > abs(ballX) - FIELD_HALF_LENGTH:  # over a touchline
        setback = -DROP_IN_SETBACK if dropInTeam == ourTeam else DROP_IN_SETBACK if dropInTeam == 1 - ourTeam else 0.0
        return clamp(ballX + setback, -lineEndX, lineEndX), lineY
    attackers = 1 - ourTeam if ballX < 0.0 else ourTeam  # of the goal whose line it left
    return (0.0 if dropInTeam == attackers else sideX * lineEndX), lineY


class Search:
    def __init__(self, supporters=TUNED):
        """supporters: the SupporterDef whose targets and homes a lost supporter uses."""
        self.supporters = supporters
        self.lastDropInTime = -1  # dropInTime at the last tick
        self.dropIn = None  # (x, y) where the ball was put back, until it is seen (the last tick's)
        self.ballPose = GoToPose()
        self.spotPose = GoToPose()

    def updateDropIn(self, blackboard):
        """Latches dropIn when the GameController's dropInTime starts again (a ball put back)
        while this robot does not see the ball; clears it once the ball is seen, or the
        drop-in is DROP_IN_FRESH_S old."""
        gc = blackboard.gameController
        localisation = blackboard.localisation
        seen = localisation.ballLostCount == 0
        if gc.dropInTime >= 0 and (self.lastDropInTime < 0 or gc.dropInTime < self.lastDropInTime) and not seen:
            self.dropIn = dropInSpot(localisation.ballPos.x, localisation.ballPos.y, gc.dropInTeam, gc.team)
        self.lastDropInTime = gc.dropInTime
        if seen or gc.dropInTime < 0 or gc.dropInTime >= DROP_IN_FRESH_S:
            self.dropIn = None

    def toBall(self, blackboard, role, ballX, ballY):
        """The walk to where the role stands for a ball at (ballX, ballY) (teamBallTarget)."""
        robotY = blackboard.localisation.robotPos.y
        self.ballPose.setTarget(*teamBallTarget(role, ballX, ballY, robotY, self.supporters))
        return self.ballPose.tick(blackboard).body

    def tick(self, blackboard, role):
        """The body request of a field player of `role` searching, or None while it has not
        lost the ball for long enough, or plays the role's own skill (a supporter walking home)."""
        self.updateDropIn(blackboard)
        if self.dropIn is not None:
            return self.toBall(blackboard, role, *self.dropIn)
        lost = blackboard.localisation.ballLostCount - SEARCH_TURN_FRAMES
        if lost <= 0:
            return None
        pos = blackboard.localisation.robotPos
        atFeet = blackboard.localisation.ballPosRR
        if atFeet.distance < BALL_AT_FEET_DIST:
            forward, left = keepClear(blackboard, -SEARCH_BACK_OFF_SPEED * math.cos(atFeet.heading),
                                      -SEARCH_BACK_OFF_SPEED * math.sin(atFeet.heading))
            return actioncommand.walk(forward, left)
        ball = teamBall(blackboard.gameController.playerNumber, blackboard.receiver.messages, blackboard.utime)
        if ball is not None:
            return self.toBall(blackboard, role, *ball)
        cycle, frame = divmod(lost - 1, SEARCH_CYCLE_FRAMES)
        if role != ROLE_STRIKER and cycle == 0:
            homeX, homeY = homePosition(role, self.supporters)
            if frame >= SEARCH_TURN_LIMIT_FRAMES or distance(pos.x, pos.y, homeX, homeY) >= HOME_NEAR_DIST:
                return None
        if frame < SEARCH_TURN_LIMIT_FRAMES:
            turn = SEARCH_TURN_SPEED if blackboard.localisation.ballPosRR.heading >= 0.0 else -SEARCH_TURN_SPEED
            return actioncommand.walk(turn=turn)
        x, y = searchSpot(role, cycle if role == ROLE_STRIKER else cycle - 1)
        self.spotPose.setTarget(x, y, 0.0)
        return self.spotPose.tick(blackboard).body
