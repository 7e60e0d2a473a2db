"""Striker: to the ball, lined up at the opponent goal (LineUpAndKick), and carries the ball on
(LineUpAndKick's carry), into the goal too. Before, it dribbled within 1000 mm of the goal's
centre; a dribble stops the walk for its swing, with the ball still, while a carry walks it
in (64 C++ matches, seeds 1-64: the ball moved 52.2 -> 53.0 % of the play)."""
from .ball import OPPONENT_GOAL_X, OPPONENT_GOAL_Y
from .line_up_and_kick import LineUpAndKick


class Striker:
    def __init__(self, policy=None):
        """policy: the learned walker's policy file to approach the ball with (None: GoToPose)."""
        self.kick = LineUpAndKick(OPPONENT_GOAL_X, OPPONENT_GOAL_Y, False, policy=policy, carry=True)

    def tick(self, blackboard):
        return self.kick.tick(blackboard)
