"""GoToBall: walk to BEHIND_BALL_DIST behind the ball, facing the goal (via GoToPose).

Uses localisation.ballPos while the ball was seen recently; otherwise stands, leaving the
head to search.
"""
import actioncommand

from .ball import BEHIND_BALL_DIST, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, ballRecentlySeen, pointBehindBall
from .go_to_pose import GoToPose


class GoToBall:
    def __init__(self, goalX=OPPONENT_GOAL_X, goalY=OPPONENT_GOAL_Y, behind=BEHIND_BALL_DIST):
        """goalX, goalY: the goal to face (mm); behind: robot-to-ball distance (mm)."""
        self.goalX = goalX
        self.goalY = goalY
        self.behind = behind
        self.goToPose = GoToPose()

    def tick(self, blackboard):
        if not ballRecentlySeen(blackboard):
            return actioncommand.compose(body=actioncommand.stand())
        x, y, theta = pointBehindBall(blackboard.localisation.ballPos, self.goalX, self.goalY, self.behind)
        self.goToPose.setTarget(x, y, theta)
        return self.goToPose.tick(blackboard)
