"""HeadScan: look at the ball while it is seen, tilting the head up the farther it is;
sweep side to side, near then far, while it is lost."""
import math

import robot

from task import Task
from commands import look

SWEEP = [(0.0, 0.3), (1.0, 0.3), (1.0, -0.5), (0.0, -0.5), (-1.0, -0.5), (-1.0, 0.3)]  # (yaw, pitch) rad
STEP_US = 500000        # at each point this long
NEAR_PITCH = 0.4        # rad down for a ball at NEAR_MM ...
FAR_PITCH = -0.4        # ... up for one at FAR_MM
NEAR_MM, FAR_MM = 500.0, 3500.0


def pitch_for(distance):
    f = max(0.0, min(1.0, (distance - NEAR_MM) / (FAR_MM - NEAR_MM)))
    return NEAR_PITCH + f * (FAR_PITCH - NEAR_PITCH)


class HeadScan(Task):
    def restart(self):
        self.index = 0
        self.since_us = None

    def act(self):
        w = self.world
        if w.ball_lost_frames() < 15:
            forward, left = w.ball_relative()
            yaw = max(robot.HeadYaw_Min, min(robot.HeadYaw_Max, math.atan2(left, forward)))
            w.request.actions.head = look(yaw, pitch_for(math.hypot(forward, left)), 0.8)
            self.since_us = None
            return
        if self.since_us is None or w.now_us() - self.since_us > STEP_US:
            self.index = (self.index + 1) % len(SWEEP)
            self.since_us = w.now_us()
        yaw, pitch = SWEEP[self.index]
        w.request.actions.head = look(yaw, pitch)
