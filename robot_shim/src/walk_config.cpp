#include <sstream>
#include <string>

#include "touchline/ini.hpp"
#include "touchline/robot/walk_cycle.hpp"

namespace touchline::robot {

namespace {

/// Throws unless `ok`, naming the file and key: "config/walk.ini: walk.period_s must be
/// > 0 (got -1)".
void require(bool ok, const std::string& path, const char* key, const char* rule, float got) {
  if (ok) return;
  std::ostringstream message;
  message << (path.empty() ? std::string("walk defaults") : path) << ": " << key << ' ' << rule
          << " (got " << got << ')';
  throw ConfigError(message.str());
}

void validate(const WalkDef& d, const std::string& path) {
  require(d.period_s > 0, path, "walk.period_s", "must be > 0", d.period_s);
  require(d.max_forward_mm_s >= 0, path, "walk.max_forward_mm_s", "must be >= 0", d.max_forward_mm_s);
  require(d.max_backward_mm_s >= 0, path, "walk.max_backward_mm_s", "must be >= 0",
          d.max_backward_mm_s);
  require(d.max_left_mm_s >= 0, path, "walk.max_left_mm_s", "must be >= 0", d.max_left_mm_s);
  require(d.max_turn_rad_s >= 0, path, "walk.max_turn_rad_s", "must be >= 0", d.max_turn_rad_s);
  require(d.accel_forward_mm_s2 > 0, path, "walk.accel_forward_mm_s2", "must be > 0",
          d.accel_forward_mm_s2);
  require(d.accel_left_mm_s2 > 0, path, "walk.accel_left_mm_s2", "must be > 0", d.accel_left_mm_s2);
  require(d.accel_turn_rad_s2 > 0, path, "walk.accel_turn_rad_s2", "must be > 0",
          d.accel_turn_rad_s2);
  require(d.foot_separation_mm > 0, path, "walk.foot_separation_mm", "must be > 0",
          d.foot_separation_mm);
  require(d.double_support >= 0 && d.double_support <= 0.9f, path, "walk.double_support",
          "must be in [0, 0.9]", d.double_support);
  require(d.swing_shape >= 0 && d.swing_shape <= 1, path, "walk.swing_shape", "must be in [0, 1]",
          d.swing_shape);
  // Side-stepping alternates the feet max_left * T/2 closer and further apart than
  // foot_separation_mm; any faster and the closing foot would cross the other.
  require(d.max_left_mm_s * d.period_s / 2 < d.foot_separation_mm, path, "walk.max_left_mm_s",
          "* walk.period_s / 2 must be < walk.foot_separation_mm", d.max_left_mm_s);
}

} // namespace

WalkDef load_walk_def(const std::string& path) {
  WalkDef def;
  IniSchema schema("walk");
  schema.bind("walk.period_s", &def.period_s, "T: full gait cycle (a step of each foot), s")
      .bind("walk.max_forward_mm_s", &def.max_forward_mm_s, "forward speed limit, mm/s")
      .bind("walk.max_backward_mm_s", &def.max_backward_mm_s, "backward speed limit, mm/s")
      .bind("walk.max_left_mm_s", &def.max_left_mm_s, "sideways speed limit, either side, mm/s")
      .bind("walk.max_turn_rad_s", &def.max_turn_rad_s, "turn rate limit, either way, rad/s")
      .bind("walk.accel_forward_mm_s2", &def.accel_forward_mm_s2,
            "forward/backward acceleration limit, mm/s^2")
      .bind("walk.accel_left_mm_s2", &def.accel_left_mm_s2, "sideways acceleration limit, mm/s^2")
      .bind("walk.accel_turn_rad_s2", &def.accel_turn_rad_s2, "turn acceleration limit, rad/s^2")
      .bind("walk.foot_separation_mm", &def.foot_separation_mm,
            "lateral distance between foot centres when standing, mm")
      .bind("walk.double_support", &def.double_support,
            "fraction of each step with both feet down, [0, 0.9]")
      .bind("walk.swing_shape", &def.swing_shape, "0 constant-speed swing .. 1 cosine ease");
  if (!path.empty()) schema.read_file(path);
  validate(def, path);
  return def;
}

} // namespace touchline::robot
