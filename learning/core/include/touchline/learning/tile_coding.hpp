#pragma once
// Tile coding over the robot-relative target (docs/learning/policy_format.md, "features
// polar-log"): u = log(1 + d / scale) makes tiles fine near the target and coarse far from
// it; the bearing to the target and the heading error wrap around the circle. Each tiling
// is a grid offset by k/K tile along u and 3k/K, 5k/K along the angles (asymmetric offsets).
// The cells come from the deployed skill's own reader (behaviour_cpp's TilePolicy, checked
// bit for bit against behaviour_py's), so training and play use the same cells.
#include <cstddef>
#include <vector>

#include "touchline/behaviour/skills/tile_policy.hpp"

namespace touchline::learning {

struct TileCodingDef {
  double distance_scale_mm = 100;   ///< d at which u = log 2; tiles are finest below it
  double max_distance_mm = 12000;   ///< u saturates beyond this (a field's diagonal)
  int tilings = 8;                  ///< K
  int tiles_distance = 10;          ///< Tu across [0, u_max] (Tu + 1 cells: offsets overhang)
  int tiles_bearing = 16;           ///< Tb around the circle
  int tiles_heading = 16;           ///< Th around the circle
};

class TileCoding {
 public:
  /// std::invalid_argument for non-positive sizes.
  explicit TileCoding(const TileCodingDef& def);

  /// Cells (per action) across all tilings.
  size_t cells() const;
  /// The K active cells for a target at (x mm forward, y mm left, heading error rad):
  /// cell = ((k (Tu + 1) + iu) Tb + ib) Th + ih. A weight's index is cell * actions + a.
  void active(double x_mm, double y_mm, double heading_rad, int* cells_out) const;
  const TileCodingDef& def() const { return def_; }

 private:
  TileCodingDef def_;
  behaviour::skills::TilePolicy cells_; ///< one action, no weights: its indices are the cells
};

} // namespace touchline::learning
