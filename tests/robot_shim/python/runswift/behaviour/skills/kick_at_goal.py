"""KickAtGoal: with the ball close in front, step so that it lies before one foot with the
goal straight ahead, then kick."""
import math

import robot

from task import Task
from commands import walk, kick
from world import GOAL_X

FOOT_Y = 50.0        # mm: a foot's centre beside the body's
BALL_AHEAD = 130.0   # mm: ball centre ahead of the body centre when kicking
TOLERANCE = 35.0     # mm
AIM = 0.2            # rad: goal within this of straight ahead
STEP_GAIN = 2.0      # (mm/s) per mm
MAX_STEP = 120.0     # mm/s


class KickAtGoal(Task):
    def restart(self):
        self.foot = None

    def act(self):
        w = self.world
        w.playing_ball = True
        bx, by = w.ball()
        mx, my, mh = w.me()
        aim = math.atan2(0.0 - by, GOAL_X - bx) - mh
        aim = math.atan2(math.sin(aim), math.cos(aim))
        forward, left = w.ball_relative()
        if self.foot is None:
            self.foot = robot.Foot.LEFT if left >= 0 else robot.Foot.RIGHT
        foot_y = FOOT_Y if self.foot == robot.Foot.LEFT else -FOOT_Y
        dx, dy = forward - BALL_AHEAD, left - foot_y
        if abs(dx) < TOLERANCE and abs(dy) < TOLERANCE and abs(aim) < AIM:
            w.request.actions.body = kick(self.foot, 1.0)
            w.last_kick_us = w.now_us()
            return
        clip = lambda v, m: max(-m, min(m, v))  # noqa: E731
        w.request.actions.body = walk(clip(STEP_GAIN * dx, MAX_STEP), clip(STEP_GAIN * dy, MAX_STEP), clip(1.5 * aim, 0.6))
