"""WalkTo: walk to a field point, turning to face it first when it is well off to the side."""
import math

from task import Task
from commands import walk

SPEED = 250.0       # mm/s
TURN_GAIN = 1.5     # rad/s per rad of heading error
MAX_TURN = 1.2      # rad/s
ARRIVED = 80.0      # mm


class WalkTo(Task):
    def act(self, x=0.0, y=0.0, face=None):
        forward, left = self.world.relative(x, y)
        distance = math.hypot(forward, left)
        self.world.walking_to = (x, y)
        heading = math.atan2(left, forward)
        if distance < ARRIVED:
            _, _, mh = self.world.me()
            error = 0.0 if face is None else math.atan2(math.sin(face - mh), math.cos(face - mh))
            self.world.request.actions.body = walk(0, 0, max(-MAX_TURN, min(MAX_TURN, TURN_GAIN * error)))
            return
        turn = max(-MAX_TURN, min(MAX_TURN, TURN_GAIN * heading))
        if abs(heading) > 0.8:  # face it first
            self.world.request.actions.body = walk(0, 0, turn)
            return
        scale = min(1.0, distance / 400.0) * SPEED / distance
        self.world.request.actions.body = walk(forward * scale, left * scale, turn)
