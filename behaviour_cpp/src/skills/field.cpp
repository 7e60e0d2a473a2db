#include "touchline/behaviour/skills/field.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::behaviour::skills {

FieldPoint clampToField(float x, float y, float margin) {
  const float limitX = FIELD_HALF_LENGTH - margin;
  const float limitY = FIELD_HALF_WIDTH - margin;
  return {std::min(std::max(x, -limitX), limitX), std::min(std::max(y, -limitY), limitY)};
}

FieldPoint clampOutOfOwnBox(float x, float y) {
  const float frontX = OWN_BOX_FRONT_X + BOX_MARGIN;
  if (x < frontX && std::fabs(y) < OWN_BOX_HALF_WIDTH + BOX_MARGIN) return {frontX, y};
  return {x, y};
}

FieldPoint avoidShootingPath(float x, float y, float ballX, float ballY, float robotY, float goalX, float goalY) {
  if (x <= ballX || goalX <= ballX) return {x, y};
  const float lineY = ballY + (goalY - ballY) * (x - ballX) / (goalX - ballX);
  if (std::fabs(y - lineY) >= SHOOTING_PATH_CLEARANCE) return {x, y};
  if (robotY >= lineY) return {x, lineY + SHOOTING_PATH_CLEARANCE};
  return {x, lineY - SHOOTING_PATH_CLEARANCE};
}

float distance(float x0, float y0, float x1, float y1) { return std::hypot(x1 - x0, y1 - y0); }

} // namespace touchline::behaviour::skills
