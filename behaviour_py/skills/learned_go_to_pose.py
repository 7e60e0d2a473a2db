"""LearnedGoToPose: walk to a field pose with a learned policy (tile_policy.TilePolicy).

Each tick the target is turned into the robot-relative state (x forward, y left, heading
error) from localisation.robotPos, in double as docs/learning/policy_format.md gives it;
inside the policy's success tolerances the robot stands, else it walks with the greedy
action. The policy file (relative to the robot's data directory) is read once per path.
"""
import math

import actioncommand
import robot

from .tile_policy import DEFAULT_POLICY, cachedPolicy


def relativeTarget(pos, x, y, theta):
    """The field pose (x, y, theta) seen from the robot at pos: (forward mm, left mm,
    heading error rad, not wrapped)."""
    dx = x - pos.x
    dy = y - pos.y
    c = math.cos(pos.theta)
    s = math.sin(pos.theta)
    return c * dx + s * dy, c * dy - s * dx, theta - pos.theta


class LearnedGoToPose:
    def __init__(self, x=0.0, y=0.0, theta=0.0, policy=DEFAULT_POLICY):
        """Target (x, y) in mm and heading theta in rad, field frame; policy: the policy
        file, relative to the robot's data directory. Raises ValueError for a bad file."""
        self.setTarget(x, y, theta)
        self.policy = cachedPolicy(robot.data_path(policy))

    def setTarget(self, x, y, theta):
        self.x = x
        self.y = y
        self.theta = theta

    def tick(self, blackboard):
        x, y, theta = relativeTarget(blackboard.localisation.robotPos, self.x, self.y, self.theta)
        if self.policy.arrived(x, y, theta):
            return actioncommand.compose(body=actioncommand.stand())
        forward, left, turn = self.policy.actions[self.policy.greedyAction(x, y, theta)]
        return actioncommand.compose(body=actioncommand.walk(forward, left, turn))
