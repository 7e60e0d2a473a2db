"""Team communication and role assignment.

Every robot sends a fixed 14-byte message (MESSAGE_SIZE) every MESSAGE_EVERY_FRAMES
frames (5 Hz at 30 Hz), little-endian:

  byte 0     MESSAGE_VERSION
  byte 1     player number (1..255)
  byte 2     role (ROLE_NONE, ROLE_GOALIE, ROLE_STRIKER, ROLE_DEFENDER, ROLE_MIDFIELDER)
  byte 3     flags: bit 0 ball seen recently, bit 1 penalised, bit 2 fallen
  bytes 4-5  uint16 distance to the ball, mm (NO_BALL_DISTANCE: not seen recently)
  bytes 6-7  int16 ball x, mm, team frame
  bytes 8-9  int16 ball y, mm, team frame
  bytes 10-11 int16 robot x, mm, team frame (where the robot believes it is: teammates
             walk around it)
  bytes 12-13 int16 robot y, mm, team frame

Millimetres are rounded half up (floor(v + 0.5)) and clamped into their field. The C++
port (team_comm.hpp) writes the same bytes for the same inputs.

Roles: player GOALIE_PLAYER is always the goalie. Among the other players that are not
penalised (this robot and every teammate whose message is at most MESSAGE_STALE_US old),
the one with the smallest ball distance is the striker (a robot already claiming striker
counts STRIKER_HYSTERESIS closer; ties go to the lower number); the rest, by player
number, alternate defender, midfielder, defender, ...
"""
import math
from dataclasses import dataclass

MESSAGE_VERSION = 2
MESSAGE_SIZE = 14                 # bytes
MESSAGE_EVERY_FRAMES = 6          # frames between messages: 5 Hz at 30 Hz
MESSAGE_STALE_US = 2000000        # us: older messages are ignored
NO_BALL_DISTANCE = 65535          # mm: the ball distance of a robot that does not see it
STRIKER_HYSTERESIS = 300          # mm: a robot claiming striker counts this much closer
GOALIE_PLAYER = 1

ROLE_NONE = 0
ROLE_GOALIE = 1
ROLE_STRIKER = 2
ROLE_DEFENDER = 3
ROLE_MIDFIELDER = 4

FLAG_BALL_SEEN = 1
FLAG_PENALISED = 2
FLAG_FALLEN = 4


@dataclass
class TeamInfo:
    """What one message says; millimetres as integers."""
    playerNumber: int = 0
    role: int = ROLE_NONE
    ballSeen: bool = False
    penalised: bool = False
    fallen: bool = False
    ballDistance: int = NO_BALL_DISTANCE
    ballX: int = 0
    ballY: int = 0
    robotX: int = 0
    robotY: int = 0


def roundMm(value, low, high):
    """value (mm) rounded half up and clamped into [low, high]."""
    value = math.floor(value + 0.5)  # an int; clamped as min(max(value, low), high) would
    return low if low > value else high if high < value else value


def makeTeamInfo(playerNumber, role, ballSeen, penalised, fallen, ballDistance, ballX, ballY, robotX=0.0, robotY=0.0):
    """A TeamInfo from Blackboard values; the ball distance is NO_BALL_DISTANCE unless
    ballSeen."""
    distanceMm = roundMm(ballDistance, 0, NO_BALL_DISTANCE - 1) if ballSeen else NO_BALL_DISTANCE
    return TeamInfo(playerNumber, role, bool(ballSeen), bool(penalised), bool(fallen), distanceMm,
                    roundMm(ballX, -32768, 32767), roundMm(ballY, -32768, 32767), roundMm(robotX, -32768, 32767),
                    roundMm(robotY, -32768, 32767))


def encodeMessage(info):
    """The MESSAGE_SIZE bytes of info."""
    flags = ((FLAG_BALL_SEEN if info.ballSeen else 0) | (FLAG_PENALISED if info.penalised else 0)
             | (FLAG_FALLEN if info.fallen else 0))
    distanceMm = min(max(info.ballDistance, 0), NO_BALL_DISTANCE)
    ballX = min(max(info.ballX, -32768), 32767) & 0xffff
    ballY = min(max(info.ballY, -32768), 32767) & 0xffff
    robotX = min(max(info.robotX, -32768), 32767) & 0xffff
    robotY = min(max(info.robotY, -32768), 32767) & 0xffff
    return bytes([MESSAGE_VERSION, info.playerNumber & 0xff, info.role & 0xff, flags,
                  distanceMm & 0xff, distanceMm >> 8, ballX & 0xff, ballX >> 8, ballY & 0xff, ballY >> 8,
                  robotX & 0xff, robotX >> 8, robotY & 0xff, robotY >> 8])


def _int16(low, high):
    value = low | (high << 8)
    return value - 0x10000 if value >= 0x8000 else value


_decoded = {}  # message bytes -> its TeamInfo: a message is decoded once, however often read


def decodeMessage(data):
    """The TeamInfo in data, or None when it is not a message of this version and size (shared
    between calls for the same bytes: read it, do not change it)."""
    info = _decoded.get(data, _decoded) if type(data) is bytes else _decoded
    if info is _decoded:
        info = _decodeMessage(data)
        if type(data) is bytes:
            if len(_decoded) >= 64:  # a few frames' messages: no need to keep more
                _decoded.clear()
            _decoded[data] = info
    return info


def _decodeMessage(data):
    if len(data) != MESSAGE_SIZE or data[0] != MESSAGE_VERSION:
        return None
    flags = data[3]
    return TeamInfo(data[1], data[2], bool(flags & FLAG_BALL_SEEN), bool(flags & FLAG_PENALISED),
                    bool(flags & FLAG_FALLEN), data[4] | (data[5] << 8), _int16(data[6], data[7]),
                    _int16(data[8], data[9]), _int16(data[10], data[11]), _int16(data[12], data[13]))


def claimDistance(ballDistance, role):
    """The ball distance a player competes for striker with."""
    if role == ROLE_STRIKER:
        return max(ballDistance - STRIKER_HYSTERESIS, 0)
    return ballDistance


def assignRole(playerNumber, ballDistance, currentRole, messages, utime):
    """This robot's role. ballDistance: its own (int mm, NO_BALL_DISTANCE when not seen);
    currentRole: its role so far; messages: blackboard.receiver.messages; utime: now (us)."""
    if playerNumber == GOALIE_PLAYER:
        return ROLE_GOALIE
    players = [(claimDistance(ballDistance, currentRole), playerNumber)]
    for message in messages:
        number = message.playerNumber
        if number == playerNumber or number == GOALIE_PLAYER:
            continue
        if utime - message.utime > MESSAGE_STALE_US:
            continue
        info = decodeMessage(message.data)
        if info is None or info.penalised:
            continue
        players.append((claimDistance(info.ballDistance, info.role), number))
    players.sort()
    if players[0][1] == playerNumber:
        return ROLE_STRIKER
    supporters = sorted(number for _, number in players[1:])
    return ROLE_DEFENDER if supporters.index(playerNumber) % 2 == 0 else ROLE_MIDFIELDER
