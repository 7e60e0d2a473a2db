#pragma once
// Team communication and role assignment: the port of behaviour_py/skills/team_comm.py.
//
// Every robot sends a fixed 14-byte message (MESSAGE_SIZE) every MESSAGE_EVERY_FRAMES
// frames (5 Hz at 30 Hz), little-endian:
//
//   byte 0     MESSAGE_VERSION
//   byte 1     player number (1..255)
//   byte 2     role (ROLE_NONE, ROLE_GOALIE, ROLE_STRIKER, ROLE_DEFENDER, ROLE_MIDFIELDER)
//   byte 3     flags: bit 0 ball seen recently, bit 1 penalised, bit 2 fallen
//   bytes 4-5  uint16 distance to the ball, mm (NO_BALL_DISTANCE: not seen recently)
//   bytes 6-7  int16 ball x, mm, team frame
//   bytes 8-9  int16 ball y, mm, team frame
//   bytes 10-11 int16 robot x, mm, team frame (where the robot believes it is: teammates
//              walk around it)
//   bytes 12-13 int16 robot y, mm, team frame
//
// Millimetres are rounded half up (floor(v + 0.5), in double as Python) and clamped into
// their field: the same bytes as the Python for the same inputs.
//
// Roles: player GOALIE_PLAYER is always the goalie. Among the other players that are not
// penalised (this robot and every teammate whose message is at most MESSAGE_STALE_US old),
// the one with the smallest ball distance is the striker (a robot already claiming striker
// counts STRIKER_HYSTERESIS closer; ties go to the lower number); the rest, by player
// number, alternate defender, midfielder, defender, ...
#include <cstdint>
#include <optional>
#include <vector>

#include "touchline/robot_api/blackboard.hpp"

namespace touchline::behaviour::skills {

inline constexpr int MESSAGE_VERSION = 2;
inline constexpr int MESSAGE_SIZE = 14;            ///< bytes
inline constexpr int MESSAGE_EVERY_FRAMES = 6;     ///< frames between messages: 5 Hz at 30 Hz
inline constexpr int MESSAGE_STALE_US = 2000000;   ///< us: older messages are ignored
inline constexpr int NO_BALL_DISTANCE = 65535;     ///< mm: the ball distance of a robot that does not see it
inline constexpr int STRIKER_HYSTERESIS = 300;     ///< mm: a robot claiming striker counts this much closer
inline constexpr int GOALIE_PLAYER = 1;

inline constexpr int ROLE_NONE = 0;
inline constexpr int ROLE_GOALIE = 1;
inline constexpr int ROLE_STRIKER = 2;
inline constexpr int ROLE_DEFENDER = 3;
inline constexpr int ROLE_MIDFIELDER = 4;

inline constexpr int FLAG_BALL_SEEN = 1;
inline constexpr int FLAG_PENALISED = 2;
inline constexpr int FLAG_FALLEN = 4;

/// What one message says; millimetres as integers.
struct TeamInfo {
  int playerNumber = 0;
  int role = ROLE_NONE;
  bool ballSeen = false;
  bool penalised = false;
  bool fallen = false;
  int ballDistance = NO_BALL_DISTANCE;
  int ballX = 0;
  int ballY = 0;
  int robotX = 0;
  int robotY = 0;
  bool operator==(const TeamInfo& o) const {
    return playerNumber == o.playerNumber && role == o.role && ballSeen == o.ballSeen && penalised == o.penalised &&
           fallen == o.fallen && ballDistance == o.ballDistance && ballX == o.ballX && ballY == o.ballY &&
           robotX == o.robotX && robotY == o.robotY;
  }
};

/// value (mm) rounded half up and clamped into [low, high].
int roundMm(double value, int low, int high);
/// A TeamInfo from Blackboard values; the ball distance is NO_BALL_DISTANCE unless ballSeen.
TeamInfo makeTeamInfo(int playerNumber, int role, bool ballSeen, bool penalised, bool fallen, float ballDistance,
                      float ballX, float ballY, float robotX = 0.f, float robotY = 0.f);
/// The MESSAGE_SIZE bytes of info.
std::vector<uint8_t> encodeMessage(const TeamInfo& info);
/// The TeamInfo in data, or nullopt when it is not a message of this version and size.
std::optional<TeamInfo> decodeMessage(const std::vector<uint8_t>& data);
/// The ball distance a player competes for striker with.
int claimDistance(int ballDistance, int role);
/// This robot's role. ballDistance: its own (mm, NO_BALL_DISTANCE when not seen);
/// currentRole: its role so far; messages: blackboard.receiver.messages; utime: now (us).
int assignRole(int playerNumber, int ballDistance, int currentRole, const std::vector<api::TeamMessage>& messages,
               int64_t utime);

} // namespace touchline::behaviour::skills
