"""Task: one node of a behaviour tree. An inner task picks which child runs this frame
(choose) and may hand it arguments; a leaf acts (act). Each node sees the shared World."""


class Task(object):
    def __init__(self, world):
        self.world = world
        self.children = self.make_children()
        self.current = None
        self.restart()

    def make_children(self):
        """{name: Task} for an inner task; {} for a leaf."""
        return {}

    def restart(self):
        """Forget this task's state (called when its parent switches to it)."""

    def choose(self):
        """An inner task: the name of the child to run now, and its arguments as a dict."""
        return None, {}

    def act(self, **kwargs):
        """A leaf: write the request (self.world.request)."""

    def step(self, **kwargs):
        self.world.trail += type(self).__name__ + "."
        if not self.children:
            self.act(**kwargs)
            return
        name, args = self.choose()
        if name != self.current:
            self.current = name
            self.children[name].restart()
        self.children[name].step(**args)
