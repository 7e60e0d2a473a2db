"""Supporter: while a teammate plays the ball (it says so in its broadcast), wait between
the ball and our goal; otherwise play it as the striker does."""
import math

from task import Task
from skills.striker import Striker
from skills.walk_to import WalkTo
from skills.stand_still import StandStill

BACK = 1200.0   # mm behind the ball, towards our goal


class Supporter(Task):
    def make_children(self):
        return {"Striker": Striker(self.world), "WalkTo": WalkTo(self.world), "Stand": StandStill(self.world)}

    def choose(self):
        w = self.world
        if not w.playing() or w.penalised() or not w.teammates_playing_ball():
            return "Striker", {}
        bx, by = w.ball()
        own_goal_x = -w.goal_x()
        angle = math.atan2(0.0 - by, own_goal_x - bx)
        return "WalkTo", {"x": bx + BACK * math.cos(angle), "y": by + BACK * math.sin(angle),
                          "face": math.atan2(by, bx)}
