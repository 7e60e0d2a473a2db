"""World: what the tasks know this frame, read from the blackboard in one place (mm, rad,
the team's own field frame: +x towards the opponent goal), plus the request being built."""
import math

import robot

GOAL_X = robot.FIELD_LENGTH / 2.0


class World(object):
    def __init__(self):
        self.blackboard = None
        self.request = None
        self.trail = ""
        self.playing_ball = False
        self.walking_to = (0.0, 0.0)
        self.last_kick_us = None
        self._frames_lost = 1000

    def update(self, blackboard):
        self.blackboard = blackboard
        if len(blackboard.vision.balls) > 0:
            self._frames_lost = 0
        else:
            self._frames_lost += 1
        self.playing_ball = False

    # --- time and the game -------------------------------------------------------------
    def now_us(self):
        return self.blackboard.vision.timestamp

    def playing(self):
        return self.blackboard.gameController.data.state == robot.STATE_PLAYING

    def ready(self):
        return self.blackboard.gameController.data.state == robot.STATE_READY

    def penalised(self):
        me = self.blackboard.gameController.player_number
        return self.blackboard.gameController.our_team.players[me - 1].penalty != robot.PENALTY_NONE

    def seconds_since_kick(self):
        if self.last_kick_us is None:
            return -1
        return int((self.now_us() - self.last_kick_us) / 1000000)

    def goal_x(self):
        return GOAL_X

    # --- where things are -----------------------------------------------------------------
    def me(self):
        pos = self.blackboard.stateEstimation.robotPos
        return pos.x, pos.y, pos.theta

    def ball_seen(self):
        return self._frames_lost == 0

    def ball_lost_frames(self):
        return self._frames_lost

    def ball(self):
        b = self.blackboard.stateEstimation.ballPos
        return b.x, b.y

    def ball_relative(self):
        b = self.blackboard.stateEstimation.ballPosRRC
        return b.x, b.y

    def relative(self, x, y):
        """A field point in the robot's frame (forward, left), mm."""
        mx, my, mh = self.me()
        dx, dy = x - mx, y - my
        c, s = math.cos(mh), math.sin(mh)
        return c * dx + s * dy, -s * dx + c * dy

    def head_yaw(self):
        return self.blackboard.motion.sensors.joints.angles[robot.Joints.HeadYaw]

    def teammates_playing_ball(self):
        me = self.blackboard.gameController.player_number
        rx = self.blackboard.receiver
        return [i + 1 for i, data in enumerate(rx.data)
                if i + 1 != me and not rx.incapacitated[i] and data.behaviourSharedData.playingBall]
