#include <string>

#include "touchline/ini.hpp"
#include "touchline/robot/head_def.hpp"

namespace touchline::robot {

namespace {

/// Half a turn either way: beyond it a yaw limit means nothing (and the world refuses a
/// head angle past pi, sim::kMaxHeadAngleRad).
constexpr float kMaxHeadAngle_rad = 3.1416f;
/// A full turn in a twentieth of a second: faster is no servo's.
constexpr float kMaxHeadSpeed_rad_s = 126.f;

/// Throws ConfigError naming the key.
void validate(const HeadDef& d) {
  require_non_negative("head.max_yaw_rad", d.max_yaw_rad, kMaxHeadAngle_rad);
  require_range("head.min_pitch_rad", d.min_pitch_rad, -kMaxHeadAngle_rad, 0.f);
  require_non_negative("head.max_pitch_rad", d.max_pitch_rad, kMaxHeadAngle_rad);
  require_positive("head.max_speed_rad_s", d.max_speed_rad_s, kMaxHeadSpeed_rad_s);
}

} // namespace

HeadDef load_head_def(const std::string& path) {
  HeadDef def;
  IniSchema schema("head");
  schema.bind("head.max_yaw_rad", &def.max_yaw_rad, "yaw limit either side, rad")
      .bind("head.min_pitch_rad", &def.min_pitch_rad, "pitch limit up (negative), rad")
      .bind("head.max_pitch_rad", &def.max_pitch_rad, "pitch limit down, rad")
      .bind("head.max_speed_rad_s", &def.max_speed_rad_s, "joint speed at yawSpeed/pitchSpeed 1, rad/s");
  if (!path.empty()) schema.read_file(path);
  try {
    validate(def);
  } catch (const ConfigError& e) { // "config/head.ini: head.max_yaw_rad must be ..."
    throw ConfigError((path.empty() ? std::string("head defaults") : path) + ": " + e.what());
  }
  return def;
}

} // namespace touchline::robot
