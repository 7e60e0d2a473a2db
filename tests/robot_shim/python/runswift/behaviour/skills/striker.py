"""Striker: find the ball, walk behind it on the line from the goal, kick it at the goal.
Before PLAYING it walks to its kick-off spot (READY) or stands; penalised, it stands."""
import math

from task import Task
from world import GOAL_X
from skills.find_ball import FindBall
from skills.walk_to import WalkTo
from skills.kick_at_goal import KickAtGoal
from skills.stand_still import StandStill

BEHIND = 250.0        # mm behind the ball, on the goal-ball line, to start the kick
CLOSE = 320.0         # mm: ball this close and in front: kick
LOST_FRAMES = 45      # frames without the ball before looking for it


class Striker(Task):
    def make_children(self):
        return {"Stand": StandStill(self.world), "FindBall": FindBall(self.world),
                "WalkTo": WalkTo(self.world), "Kick": KickAtGoal(self.world)}

    def choose(self):
        w = self.world
        if w.penalised() or not (w.playing() or w.ready()):
            return "Stand", {}
        if w.ready():
            me = w.blackboard.gameController.player_number
            return "WalkTo", {"x": -600.0 * me, "y": 0.0, "face": 0.0}
        bx, by = w.ball()
        forward, left = w.ball_relative()
        distance = math.hypot(forward, left)
        if w.ball_lost_frames() > LOST_FRAMES:
            # Lost: go where it was believed to be, then look around there.
            if distance > 700 and self.current != "FindBall":
                return "WalkTo", {"x": bx, "y": by}
            return "FindBall", {}
        if distance < CLOSE and forward > 0 and abs(math.atan2(left, forward)) < 0.7:
            return "Kick", {}
        angle = math.atan2(0.0 - by, GOAL_X - bx)
        return "WalkTo", {"x": bx - BEHIND * math.cos(angle), "y": by - BEHIND * math.sin(angle), "face": angle}
