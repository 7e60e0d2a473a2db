"""StandStill: a leaf that stands (a skill for tests, and what a penalised robot does)."""
from task import Task
from commands import stand


class StandStill(Task):
    def act(self):
        self.world.request.actions.body = stand()
