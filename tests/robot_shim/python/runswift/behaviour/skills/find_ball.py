"""FindBall: turn on the spot for about one turn (towards where the ball was last believed
to be; the direction is kept, so that a belief drifting across straight ahead does not
make the robot turn back and forth), then walk a few seconds towards the opponent goal,
where a kicked ball usually went, and turn again."""
import math

from task import Task
from commands import walk
from world import GOAL_X

TURN_RATE = 0.8    # rad/s
TURN_US = 8000000  # about one turn
WALK_US = 3000000


class FindBall(Task):
    def restart(self):
        self.turn = None
        self.since_us = self.world.now_us() if self.world.blackboard is not None else 0

    def act(self):
        w = self.world
        if self.turn is None:
            _, left = w.ball_relative()
            self.turn = TURN_RATE if left >= 0 else -TURN_RATE
        elapsed = (w.now_us() - self.since_us) % (TURN_US + WALK_US)
        if elapsed < TURN_US:
            w.request.actions.body = walk(0, 0, self.turn)
            return
        forward, left = w.relative(GOAL_X, 0.0)
        heading = math.atan2(left, forward)
        w.request.actions.body = walk(200 if abs(heading) < 0.5 else 0, 0, max(-1.0, min(1.0, 1.5 * heading)))
