"""GoToBall: walk to BEHIND_BALL_DIST behind the ball, facing the goal, or along the line a
ball on it lies on (ball.py's kickAim) (via GoToPose, or LearnedGoToPose when given a policy).

Uses localisation.ballPos while the ball was seen recently; otherwise stands, leaving the
head to search.
"""
import actioncommand

from .ball import BEHIND_BALL_DIST, OPPONENT_GOAL_X, OPPONENT_GOAL_Y, ballRecentlySeen, kickAim, pointBehindBall
from .go_to_pose import GoToPose
from .learned_go_to_pose import LearnedGoToPose


class GoToBall:
    def __init__(self, goalX=OPPONENT_GOAL_X, goalY=OPPONENT_GOAL_Y, behind=BEHIND_BALL_DIST, policy=None):
        """goalX, goalY: the goal to face (mm); behind: robot-to-ball distance (mm); policy:
        None to walk with GoToPose, else the learned policy's file (data-relative) to walk
        with LearnedGoToPose."""
        self.goalX = goalX
        self.goalY = goalY
        self.behind = behind
        self.goToPose = GoToPose() if policy is None else LearnedGoToPose(policy=policy)

    def tick(self, blackboard):
        if not ballRecentlySeen(blackboard):
            return actioncommand.compose(body=actioncommand.stand())
        ball = blackboard.localisation.ballPos
        aimX, aimY = kickAim(ball.x, ball.y, self.goalX, self.goalY, self.behind)
        x, y, theta = pointBehindBall(ball, aimX, aimY, self.behind)
        self.goToPose.setTarget(x, y, theta)
        return self.goToPose.tick(blackboard)
