"""HeadScan: sweep the head yaw across the joint range at a steady pace, mid pitch.

Driven by its own frame count (one step per tick), never by wall time: the yaw is
SCAN_YAW_STEP times an integer step that walks between -SCAN_STEPS and SCAN_STEPS.
"""
import math

import actioncommand

from .robot_limits import MAX_HEAD_PITCH, MAX_HEAD_YAW, MIN_HEAD_PITCH, clamp

SCAN_STEPS = 40                                    # frames from centre to either side
SCAN_YAW_STEP = MAX_HEAD_YAW / SCAN_STEPS          # rad per frame (1.56 rad/s at 30 Hz)
SCAN_PITCH = (MIN_HEAD_PITCH + MAX_HEAD_PITCH) / 2  # rad: mid pitch


class HeadScan:
    def __init__(self):
        self.reset()

    def reset(self):
        """Start afresh at the next tick: from the head's yaw, towards the ball's side."""
        self.started = False
        self.step = 0
        self.direction = 1

    def tick(self, blackboard):
        if not self.started:
            yaw = clamp(blackboard.motion.headYaw, -MAX_HEAD_YAW, MAX_HEAD_YAW)
            # Nearest step: the head often rests on one exactly (the limits included), where
            # truncation could fall either side in float32 and float64.
            self.step = int(math.floor(yaw / SCAN_YAW_STEP + 0.5))
            self.direction = 1 if blackboard.localisation.ballPosRR.heading >= 0.0 else -1
            self.started = True
        self.step += self.direction
        if self.step >= SCAN_STEPS:
            self.step = SCAN_STEPS
            self.direction = -1
        elif self.step <= -SCAN_STEPS:
            self.step = -SCAN_STEPS
            self.direction = 1
        return actioncommand.compose(head=actioncommand.head(self.step * SCAN_YAW_STEP, SCAN_PITCH))
