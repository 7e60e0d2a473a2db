"""Stand: the body skill that does nothing (for head-only skills)."""
import actioncommand


class Stand:
    def tick(self, blackboard):
        return actioncommand.compose(body=actioncommand.stand())
