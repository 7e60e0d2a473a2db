"""Building the body and head requests of the robot API (their units: mm/s, rad/s, rad)."""
import robot


def _body(action, forward=0, left=0, turn=0.0, power=0.0, foot=robot.Foot.LEFT, speed=1.0):
    return robot.BodyCommand(action, int(forward), int(left), float(turn), float(power), 0.0, float(speed),
                             foot, False, False, False, False, False)


def walk(forward, left, turn, speed=1.0):
    return _body(robot.ActionType.WALK, forward, left, turn, speed=speed)


def stand():
    return _body(robot.ActionType.STAND)


def kick(foot, power=1.0, direction=0.0):
    return _body(robot.ActionType.KICK, turn=direction, power=power, foot=foot)


def look(yaw, pitch, yaw_speed=0.5):
    return robot.HeadCommand(float(yaw), float(pitch), False, float(yaw_speed), 0.5)
