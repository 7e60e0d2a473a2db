#include "touchline/behaviour/skills/team_comm.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace touchline::behaviour::skills {

int roundMm(double value, int low, int high) {
  const double rounded = std::floor(value + 0.5);
  if (rounded < low) return low;
  if (rounded > high) return high;
  return static_cast<int>(rounded);
}

TeamInfo makeTeamInfo(int playerNumber, int role, bool ballSeen, bool penalised, bool fallen, float ballDistance,
                      float ballX, float ballY, float robotX, float robotY) {
  const int distanceMm = ballSeen ? roundMm(ballDistance, 0, NO_BALL_DISTANCE - 1) : NO_BALL_DISTANCE;
  return {playerNumber, role, ballSeen, penalised, fallen, distanceMm, roundMm(ballX, -32768, 32767),
          roundMm(ballY, -32768, 32767), roundMm(robotX, -32768, 32767), roundMm(robotY, -32768, 32767)};
}

std::vector<uint8_t> encodeMessage(const TeamInfo& info) {
  const int flags = (info.ballSeen ? FLAG_BALL_SEEN : 0) | (info.penalised ? FLAG_PENALISED : 0) |
                    (info.fallen ? FLAG_FALLEN : 0);
  const int distanceMm = std::min(std::max(info.ballDistance, 0), NO_BALL_DISTANCE);
  const int ballX = std::min(std::max(info.ballX, -32768), 32767) & 0xffff;
  const int ballY = std::min(std::max(info.ballY, -32768), 32767) & 0xffff;
  const int robotX = std::min(std::max(info.robotX, -32768), 32767) & 0xffff;
  const int robotY = std::min(std::max(info.robotY, -32768), 32767) & 0xffff;
  return {static_cast<uint8_t>(MESSAGE_VERSION),  static_cast<uint8_t>(info.playerNumber & 0xff),
          static_cast<uint8_t>(info.role & 0xff), static_cast<uint8_t>(flags),
          static_cast<uint8_t>(distanceMm & 0xff), static_cast<uint8_t>(distanceMm >> 8),
          static_cast<uint8_t>(ballX & 0xff),      static_cast<uint8_t>(ballX >> 8),
          static_cast<uint8_t>(ballY & 0xff),      static_cast<uint8_t>(ballY >> 8),
          static_cast<uint8_t>(robotX & 0xff),     static_cast<uint8_t>(robotX >> 8),
          static_cast<uint8_t>(robotY & 0xff),     static_cast<uint8_t>(robotY >> 8)};
}

namespace {

int int16(uint8_t low, uint8_t high) {
  const int value = low | (high << 8);
  return value >= 0x8000 ? value - 0x10000 : value;
}

} // namespace

std::optional<TeamInfo> decodeMessage(const std::vector<uint8_t>& data) {
  if (data.size() != static_cast<size_t>(MESSAGE_SIZE) || data[0] != MESSAGE_VERSION) return std::nullopt;
  const int flags = data[3];
  return TeamInfo{data[1],
                  data[2],
                  (flags & FLAG_BALL_SEEN) != 0,
                  (flags & FLAG_PENALISED) != 0,
                  (flags & FLAG_FALLEN) != 0,
                  data[4] | (data[5] << 8),
                  int16(data[6], data[7]),
                  int16(data[8], data[9]),
                  int16(data[10], data[11]),
                  int16(data[12], data[13])};
}

int claimDistance(int ballDistance, int role) {
  if (role == ROLE_STRIKER) return std::max(ballDistance - STRIKER_HYSTERESIS, 0);
  return ballDistance;
}

int assignRole(int playerNumber, int ballDistance, int currentRole, const std::vector<api::TeamMessage>& messages,
               int64_t utime) {
  if (playerNumber == GOALIE_PLAYER) return ROLE_GOALIE;
  std::vector<std::pair<int, int>> players = {{claimDistance(ballDistance, currentRole), playerNumber}};
  for (const api::TeamMessage& message : messages) {
    const int number = message.playerNumber;
    if (number == playerNumber || number == GOALIE_PLAYER) continue;
    if (utime - message.utime > MESSAGE_STALE_US) continue;
    const std::optional<TeamInfo> info = decodeMessage(message.data);
    if (!info || info->penalised) continue;
    players.emplace_back(claimDistance(info->ballDistance, info->role), number);
  }
  std::sort(players.begin(), players.end());
  if (players[0].second == playerNumber) return ROLE_STRIKER;
  std::vector<int> supporters;
  for (size_t i = 1; i < players.size(); ++i) supporters.push_back(players[i].second);
  std::sort(supporters.begin(), supporters.end());
  const auto index = std::find(supporters.begin(), supporters.end(), playerNumber) - supporters.begin();
  return index % 2 == 0 ? ROLE_DEFENDER : ROLE_MIDFIELDER;
}

} // namespace touchline::behaviour::skills
