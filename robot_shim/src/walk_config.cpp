#include <sstream>
#include <string>

#include "touchline/ini.hpp"
#include "touchline/robot/walk_cycle.hpp"

namespace touchline::robot {

namespace {

// Ranges: generous, but a walk within them cannot fling a foot across the field in one
// tick. The world turns the feet's motion into Box2D velocities, so an absurd walk speed
// became an absurd body velocity.
/// A step of each foot lasts at least one 10 ms motion tick; ten seconds is no walk.
constexpr float kMinPeriod_s = 0.02f, kMaxPeriod_s = 10.f;
/// Over three times a Nao's fastest walk (about 300 mm/s forward).
constexpr float kMaxSpeed_mm_s = 1000.f;
/// A full turn a second.
constexpr float kMaxTurn_rad_s = 6.3f;
/// One g, and a full turn a second gained in a twentieth of a second.
constexpr float kMaxAccel_mm_s2 = 10000.f, kMaxAccelTurn_rad_s2 = 126.f;
/// Feet a metre apart are no Nao's.
constexpr float kMaxFootSeparation_mm = 1000.f;

/// Throws ConfigError naming the key: "walk.period_s must be in [0.02, 10] (got -1)".
void validate(const WalkDef& d) {
  require_range("walk.period_s", d.period_s, kMinPeriod_s, kMaxPeriod_s);
  require_non_negative("walk.max_forward_mm_s", d.max_forward_mm_s, kMaxSpeed_mm_s);
  require_non_negative("walk.max_backward_mm_s", d.max_backward_mm_s, kMaxSpeed_mm_s);
  require_non_negative("walk.max_left_mm_s", d.max_left_mm_s, kMaxSpeed_mm_s);
  require_non_negative("walk.max_turn_rad_s", d.max_turn_rad_s, kMaxTurn_rad_s);
  require_positive("walk.accel_forward_mm_s2", d.accel_forward_mm_s2, kMaxAccel_mm_s2);
  require_positive("walk.accel_left_mm_s2", d.accel_left_mm_s2, kMaxAccel_mm_s2);
  require_positive("walk.accel_turn_rad_s2", d.accel_turn_rad_s2, kMaxAccelTurn_rad_s2);
  require_positive("walk.foot_separation_mm", d.foot_separation_mm, kMaxFootSeparation_mm);
  require_range("walk.double_support", d.double_support, 0, 0.9f);
  require_fraction("walk.swing_shape", d.swing_shape);
  // Side-stepping alternates the feet max_left * T/2 closer and further apart than
  // foot_separation_mm; any faster and the closing foot would cross the other.
  if (!(d.max_left_mm_s * d.period_s / 2 < d.foot_separation_mm)) {
    std::ostringstream message;
    message << "walk.max_left_mm_s * walk.period_s / 2 must be < walk.foot_separation_mm (got "
            << d.max_left_mm_s << ")";
    throw ConfigError(message.str());
  }
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
  try {
    validate(def);
  } catch (const ConfigError& e) { // "config/walk.ini: walk.period_s must be ..."
    throw ConfigError((path.empty() ? std::string("walk defaults") : path) + ": " + e.what());
  }
  return def;
}

} // namespace touchline::robot
