"""LineUpAndKick: approach the ball (GoToBall), line the kicking foot up behind it facing the
goal (or along the line a ball on it lies on: ball.py's kickAim) with small steps, and kick
(or dribble) once aligned.

The foot is chosen on the ball's side when lining up starts and kept until it ends. The aim
may be off by KICK_FAR_ANGLE_TOLERANCE while the goal is far; while a robot (avoid.py's
obstacles) is within CONTEST_DIST of the ball, the robot kicks at once wherever the kick
gains ground (CONTEST_ANGLE_TOLERANCE) instead of turning slowly under its feet, the ball
placed as for any kick (KICK_X/Y_TOLERANCE): the swing reaches 200 mm ahead of the body
centre (the toe 80 plus the strike's 120), so a contested kick once allowed 80 mm beyond the
kicking spot (210) met the ball at the end of the swing, and one 70 mm off the foot's line
with its edge: kicks that glanced off or missed. A contest in which the ball has not moved
STALL_BALL_MOVE for STALL_FRAMES (kicks into an opponent's feet, the ball wedged) makes the
robot step sideways round the ball, away from the nearest robot, for SIDESTEP_FRAMES, so the
next kick has a clear line. Lining-up steps and sidesteps
go through avoid's keepClear: off touched sectors (they were most of the pushing fouls left
once Avoid's walks kept off them), out of the own goal box (stepping into it while lining up
was most of the illegal-defender calls with balls put back on the throw-in line: 16 C++
matches, 1.44 a match for both teams, 0.63 through keepClear) and on the field.

With `carry`, a ball lined up within CARRY_ANGLE, ahead and near the body's centre line, is
walked into at CARRY_SPEED instead of kicked (closing on a ball further ahead faster, up to
MAX_FORWARD: carrySpeed): the feet push it on and the walk follows it,
turning towards the aim, with no kick's stop (about 2.2 s of the ball lying still under a
standing robot). A robot ahead does not stop it: a kick into a robot at the ball often
rebounds, sometimes out of the field. keepClear stops the walk at a touch, but in a contest
the carrier leans on at up to CONTEST_LEAN_SPEED (the rules call no pushing while both robots
are at the ball): two robots that stopped at each other's feet held the ball between them.
A carrier starts lining up with the aim up to CARRY_ANGLE off, beyond a right angle: it turns
with the ball towards the aim, the ball moving all the while, rather than walking round the
ball first (at 1.2 rad, where the ball still gains ground, it moved 1.2 % less of the play, 16
matches). In a contest a carrier also steps sideways at CONTEST_DODGE_SPEED, away from the robot
nearest the ball: two carriers walking into one ball from both sides wedge it between their
feet, and the sideways step rolls it off the pair. Carrying walks go through avoid's keepClear,
as Avoid's do.
"""
import math

import actioncommand
import robot

from .avoid import keepClear, keepInBounds, obstacles, remember
from .ball import BEHIND_BALL_DIST, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, ballRecentlySeen, kickAim
from .go_to_ball import GoToBall
from .go_to_pose import TURN_GAIN
from .robot_limits import MAX_FORWARD, clamp

FOOT_OFFSET = 50.0                         # mm: each foot's centre left/right of the body centre
KICK_BALL_X = 130.0                        # mm: ball centre ahead of the body centre to kick (toe 80 + radius 32.5 + gap)
KICK_X_TOLERANCE = 40.0                    # mm
KICK_Y_TOLERANCE = 40.0                    # mm: ball centre from the kicking foot's centre line
KICK_ANGLE_TOLERANCE = math.radians(10)    # rad: heading error to the goal ...
KICK_FAR_DIST = 2500.0                     # mm: ... or, the ball farther than this from it, ...
KICK_FAR_ANGLE_TOLERANCE = 0.45            # rad: ... this (the kick still gains ground)
CONTEST_DIST = 500.0                       # mm: an obstacle this near the ball contests it: then ...
CONTEST_ANGLE_TOLERANCE = 1.2              # rad: ... kick this far off the goal
STALL_FRAMES = 60                          # frames (2 s) contested without the ball moving ...
STALL_BALL_MOVE = 100.0                    # mm: ... this far: then ...
SIDESTEP_FRAMES = 30                       # frames (1 s) of stepping sideways round the ball
LINE_UP_ENTER_DIST = 300.0                 # mm: start lining up when the ball is this close ...
LINE_UP_ENTER_ANGLE = 1.2                  # rad: ... ahead (steps sideways to it: at 0.6 the ball moved 0.6 % less of the play), and the goal this well in line
LINE_UP_LEAVE_DIST = 500.0                 # mm: back to approaching beyond this ...
LINE_UP_LEAVE_ANGLE = 1.5                  # rad: ... or this far off
LINE_UP_GAIN = 2.0                         # 1/s: step request (mm/s) per mm of error
LINE_UP_MAX_SPEED = 250.0                  # mm/s: steps, either axis (at 150 the ball moved 1.4 % less of the play)
LINE_UP_MAX_TURN = 1.0                     # rad/s
KICK_POWER = 1.0                           # default power of a kick ...
DRIBBLE_POWER = 1.0                        # ... and of a dribble (about 1 m)
CARRY_ANGLE = 1.8                          # rad: with carry, the aim this well in line (lining up starts so too), ...
CARRY_BALL_X = 400.0                       # mm: ... the ball ahead within this ...
CARRY_BALL_Y = 120.0                       # mm: ... and this near the body's centre line: ...
# mm/s: ... walk into the ball at this (at full speed the feet strike it away; 64 C++ matches,
# seeds 1-64: at 180 the ball moved 51.0 % of the play, at 140 52.2 %; 100-230 on seeds 1-16:
# 46.6, 51.2, 52.6 (140), 52.0, 52.3, 51.0 (180), 49.8 %) ...
CARRY_SPEED = 140.0
CARRY_CLOSING_GAIN = 2.0                   # 1/s: ... plus this per mm it lies beyond KICK_BALL_X, up to MAX_FORWARD
CONTEST_DODGE_SPEED = 150.0                # mm/s: a carrier in a contest steps this much sideways, away from
                                           # the robot nearest the ball (64 C++ matches, seeds 1-64: the ball
                                           # still between both teams 13.1 -> 11.0 % of the play, moving 50.2 ->
                                           # 51.0 %; at 80 and 250 mm/s, seeds 1-16, 50.3 and 50.4 % against 51.0 %)
CONTEST_LEAN_SPEED = 85.0                  # mm/s: a carrier in a contest that a touch would stop leans on into it
                                           # at up to this (the rules call no pushing while both robots are at the
                                           # ball); two that stopped at each other's feet held the ball between them
                                           # (16 C++ matches on each of seeds 1-16, 17-32 and 33-48, with a trial
                                           # build whose lean skipped keepInBounds: the ball moving 55.0, 55.3 and
                                           # 55.4 -> 59.5 % of the play on each, pushing 0.2-0.6 -> 1.1-1.6 calls a
                                           # team a match; at 70 mm/s 58.1 and 58.4 % on the first two, at 100 59.2
                                           # and 59.1 %, at 140 59.9 % on seeds 1-16, where the four strikers gained
                                           # most on the supporters; as committed, 58.7 % on seeds 1-16: within a
                                           # 16-match run's spread of the trial's, as without keepInBounds again
                                           # 59.4-59.7 % and with 150 mm of slack beyond the lines 58.7 %)


def carrySpeed(ballX):
    """The forward speed of a carry with the ball `ballX` mm ahead of the body centre:
    CARRY_SPEED at the foot (KICK_BALL_X), faster further out (CARRY_CLOSING_GAIN), up to
    MAX_FORWARD; at a constant 180 mm/s (CARRY_SPEED then: 1.5 s to a ball 400 mm ahead) the
    ball moved 1.6 % less of the play."""
    return clamp(CARRY_SPEED + CARRY_CLOSING_GAIN * (ballX - KICK_BALL_X), CARRY_SPEED, MAX_FORWARD)


class LineUpAndKick:
    def __init__(self, goalX=OPPONENT_GOAL_X, goalY=OPPONENT_GOAL_Y, dribble=False, power=None, policy=None,
                 carry=False):
        """goalX, goalY: where to kick (mm); dribble: dribble instead of kicking; power:
        [0, 1], None for KICK_POWER or DRIBBLE_POWER; policy: GoToBall's (None: GoToPose);
        carry: walk the ball on instead of kicking it, past a robot ahead too."""
        self.goalX = goalX
        self.goalY = goalY
        self.dribble = dribble
        self.carry = carry
        if power is None:
            power = DRIBBLE_POWER if dribble else KICK_POWER
        self.power = power
        self.goToBall = GoToBall(goalX, goalY, BEHIND_BALL_DIST, policy)
        self.liningUp = False
        self.foot = robot.Foot.LEFT
        self.seen = []  # the robots the camera saw (avoid.remember)
        self.contested = False
        self.aimTolerance = KICK_ANGLE_TOLERANCE  # this tick's: normal, far or contested
        self.stalledFrames = 0  # contested frames without the ball moving STALL_BALL_MOVE from stallBall
        self.stallBall = (0.0, 0.0)
        self.sidestepFrames = 0  # sidestep frames left, at sidestepLeft mm/s
        self.sidestepLeft = 0.0

    def tick(self, blackboard):
        if not ballRecentlySeen(blackboard):
            self.liningUp = False
            return actioncommand.compose(body=actioncommand.stand())
        pos = blackboard.localisation.robotPos
        ball = blackboard.localisation.ballPos
        ballRR = robot.toRobotRelative(pos, ball.x, ball.y)
        aimX, aimY = kickAim(ball.x, ball.y, self.goalX, self.goalY, BEHIND_BALL_DIST)
        aimError = robot.normaliseTheta(math.atan2(aimY - ball.y, aimX - ball.x) - pos.theta)
        self.seen = remember(self.seen, blackboard)
        nearest, nearestY = CONTEST_DIST, 0.0  # the obstacle nearest the ball within CONTEST_DIST
        for x, y in obstacles(blackboard, self.seen):
            dist = math.hypot(x - ballRR.x(), y - ballRR.y())
            if dist < nearest:
                nearest, nearestY = dist, y
        self.contested = nearest < CONTEST_DIST
        awaySide = -1.0 if nearestY > ballRR.y() else 1.0  # sideways away from that obstacle: + left
        far = math.hypot(self.goalX - ball.x, self.goalY - ball.y) > KICK_FAR_DIST
        self.aimTolerance = (CONTEST_ANGLE_TOLERANCE if self.contested
                             else KICK_FAR_ANGLE_TOLERANCE if far else KICK_ANGLE_TOLERANCE)
        self.updateLiningUp(ballRR, aimError)
        if not self.liningUp:
            self.stalledFrames = self.sidestepFrames = 0
            return self.goToBall.tick(blackboard)
        if self.sidestepFrames > 0:  # a stalled contest: step round the ball for a clear kick
            self.sidestepFrames -= 1
            turn = clamp(TURN_GAIN * ballRR.heading, -LINE_UP_MAX_TURN, LINE_UP_MAX_TURN)
            forward, left = keepClear(blackboard, 0.0, self.sidestepLeft)
            return actioncommand.compose(body=actioncommand.walk(forward, left, turn))
        if self.contested and math.hypot(ball.x - self.stallBall[0], ball.y - self.stallBall[1]) < STALL_BALL_MOVE:
            self.stalledFrames += 1
            if self.stalledFrames >= STALL_FRAMES:
                self.stalledFrames = 0
                self.sidestepFrames = SIDESTEP_FRAMES
                self.sidestepLeft = awaySide * LINE_UP_MAX_SPEED
        else:
            self.stalledFrames = 0
            self.stallBall = (ball.x, ball.y)
        if (self.carry and abs(aimError) < CARRY_ANGLE
                and 0.0 < ballRR.x() < CARRY_BALL_X and abs(ballRR.y()) < CARRY_BALL_Y):
            dodge = awaySide * CONTEST_DODGE_SPEED if self.contested else 0.0
            left = clamp(LINE_UP_GAIN * ballRR.y() + dodge, -LINE_UP_MAX_SPEED, LINE_UP_MAX_SPEED)
            turn = clamp(TURN_GAIN * aimError, -LINE_UP_MAX_TURN, LINE_UP_MAX_TURN)
            speed = carrySpeed(ballRR.x())
            forward, cleared = keepClear(blackboard, speed, left)
            lean = min(CONTEST_LEAN_SPEED, speed)
            if self.contested and forward < lean:  # into the contest, not away
                forward, cleared = keepInBounds(blackboard, lean, left)
            return actioncommand.compose(body=actioncommand.walk(forward, cleared, turn))
        body = self.lineUp(ballRR, aimError)
        if body.actionType == robot.ActionType.WALK:
            body.forward, body.left = keepClear(blackboard, body.forward, body.left)
        return actioncommand.compose(body=body)

    def updateLiningUp(self, ballRR, aimError):
        if self.liningUp:
            self.liningUp = (ballRR.distance < LINE_UP_LEAVE_DIST and abs(ballRR.heading) < LINE_UP_LEAVE_ANGLE
                             and abs(aimError) < max(LINE_UP_LEAVE_ANGLE, self.aimTolerance))
            return
        self.liningUp = (ballRR.distance < LINE_UP_ENTER_DIST and abs(ballRR.heading) < LINE_UP_ENTER_ANGLE
                         and abs(aimError) < max(LINE_UP_ENTER_ANGLE, self.aimTolerance,
                                                 CARRY_ANGLE if self.carry else 0.0))
        if self.liningUp:
            self.foot = robot.Foot.LEFT if ballRR.y() >= 0.0 else robot.Foot.RIGHT

    def footY(self):
        return FOOT_OFFSET if self.foot == robot.Foot.LEFT else -FOOT_OFFSET

    def lineUp(self, ballRR, aimError):
        """Kick when the ball is in front of the foot and the goal ahead; else step closer."""
        xError = ballRR.x() - KICK_BALL_X
        yError = ballRR.y() - self.footY()
        if abs(xError) < KICK_X_TOLERANCE and abs(yError) < KICK_Y_TOLERANCE and abs(aimError) < self.aimTolerance:
            if self.dribble:
                return actioncommand.dribble(self.power, self.foot)
            return actioncommand.kick(self.power, self.foot)
        forward = clamp(LINE_UP_GAIN * xError, -LINE_UP_MAX_SPEED, LINE_UP_MAX_SPEED)
        left = clamp(LINE_UP_GAIN * yError, -LINE_UP_MAX_SPEED, LINE_UP_MAX_SPEED)
        turn = clamp(TURN_GAIN * aimError, -LINE_UP_MAX_TURN, LINE_UP_MAX_TURN)
        return actioncommand.walk(forward, left, turn)
