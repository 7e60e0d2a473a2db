#include "touchline/learning/tile_coding.hpp"

#include <stdexcept>

namespace touchline::learning {

namespace {
behaviour::skills::TilePolicyDef cells_only(const TileCodingDef& def) {
  if (def.distance_scale_mm <= 0 || def.max_distance_mm <= 0 || def.tilings < 1 || def.tiles_distance < 1 ||
      def.tiles_bearing < 1 || def.tiles_heading < 1)
    throw std::invalid_argument("tile coding: sizes must be positive");
  behaviour::skills::TilePolicyDef policy;
  policy.distanceScale = def.distance_scale_mm;
  policy.maxDistance = def.max_distance_mm;
  policy.tilings = def.tilings;
  policy.tilesU = def.tiles_distance;
  policy.tilesB = def.tiles_bearing;
  policy.tilesH = def.tiles_heading;
  policy.actions.resize(1); // a weight index per cell
  return policy;
}
} // namespace

TileCoding::TileCoding(const TileCodingDef& def) : def_(def), cells_(cells_only(def)) {}

size_t TileCoding::cells() const {
  return static_cast<size_t>(def_.tilings) * static_cast<size_t>(def_.tiles_distance + 1) *
         static_cast<size_t>(def_.tiles_bearing) * static_cast<size_t>(def_.tiles_heading);
}

void TileCoding::active(double x_mm, double y_mm, double heading_rad, int* cells_out) const {
  const std::vector<size_t> cells = cells_.cellIndices(x_mm, y_mm, heading_rad);
  for (size_t k = 0; k < cells.size(); ++k) cells_out[k] = static_cast<int>(cells[k]);
}

} // namespace touchline::learning
