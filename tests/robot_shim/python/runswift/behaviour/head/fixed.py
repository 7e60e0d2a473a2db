"""HeadFixed: the head straight ahead, tilted down."""
from task import Task
from commands import look


class HeadFixed(Task):
    def act(self):
        self.world.request.actions.head = look(0.0, 0.35)
