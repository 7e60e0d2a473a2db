#include <string>

#include "touchline/ini.hpp"
#include "touchline/robot/kick_generator.hpp"

namespace touchline::robot {

namespace {

/// Above this the world would fling the foot faster than any Nao leg swings (a Nao
/// kick's foot peaks at about 1-2 m/s), and nothing else clamps it.
constexpr float kMaxFootSpeed_mm_s = 3000.f;
/// A bend beyond this would swing the foot sideways across the other foot.
constexpr float kMaxBend_rad = 1.0f;

/// A foot's reach: no kick draws back or swings through further than this.
constexpr float kMaxSwing_mm = 1000.f;
/// Standing before and after a kick: ten seconds of it is no kick.
constexpr float kMaxPause_s = 10.f;
/// Turning to bend and back: a full turn in a twentieth of a second.
constexpr float kMaxAimSpeed_rad_s = 126.f;

/// Throws ConfigError naming the key: "kick.prepare_s must be in [0, 10] (got -1)".
void validate(const SwingDef& d, const std::string& section) {
  auto key = [&](const char* name) { return section + "." + name; };
  require_non_negative(key("prepare_s").c_str(), d.prepare_s, kMaxPause_s);
  require_non_negative(key("backswing_mm").c_str(), d.backswing_mm, kMaxSwing_mm);
  require_positive(key("swing_length_mm").c_str(), d.swing_length_mm, kMaxSwing_mm);
  require_positive(key("peak_speed_mm_s").c_str(), d.peak_speed_mm_s, kMaxFootSpeed_mm_s);
  require_positive(key("min_power").c_str(), d.min_power, 1);
  require_positive(key("reposition_speed_mm_s").c_str(), d.reposition_speed_mm_s, kMaxFootSpeed_mm_s);
  require_positive(key("aim_speed_rad_s").c_str(), d.aim_speed_rad_s, kMaxAimSpeed_rad_s);
  require_non_negative(key("max_bend_rad").c_str(), d.max_bend_rad, kMaxBend_rad);
  require_non_negative(key("recover_s").c_str(), d.recover_s, kMaxPause_s);
}

/// Binds every SwingDef field under `section` (the keys' names are the fields' names).
void bind_swing(IniSchema& schema, const std::string& section, SwingDef& d) {
  // program_options copies the name, so a temporary string is enough.
  auto bind = [&](const char* name, float* field, const char* description) {
    schema.bind((section + "." + name).c_str(), field, description);
  };
  bind("prepare_s", &d.prepare_s, "standing still after the walk stops, s");
  bind("backswing_mm", &d.backswing_mm, "wind-up: the foot draws back this far, mm");
  bind("swing_length_mm", &d.swing_length_mm, "the strike ends this far ahead, mm");
  bind("peak_speed_mm_s", &d.peak_speed_mm_s, "strike's peak foot speed at power 1, mm/s");
  bind("min_power", &d.min_power, "lower powers swing at this power, (0, 1]");
  bind("reposition_speed_mm_s", &d.reposition_speed_mm_s,
       "peak foot speed of the wind-up and the return, mm/s");
  bind("aim_speed_rad_s", &d.aim_speed_rad_s, "peak turn rate to bend and back, rad/s");
  bind("max_bend_rad", &d.max_bend_rad, "|bend| is clamped to this, rad");
  bind("recover_s", &d.recover_s, "standing still after the swing, s");
}

} // namespace

KickDef load_kick_def(const std::string& path) {
  KickDef def;
  IniSchema schema("kick");
  bind_swing(schema, "kick", def.kick);
  bind_swing(schema, "dribble", def.dribble);
  if (!path.empty()) schema.read_file(path);
  try {
    validate(def.kick, "kick");
    validate(def.dribble, "dribble");
  } catch (const ConfigError& e) { // "config/kick.ini: kick.prepare_s must be ..."
    throw ConfigError((path.empty() ? std::string("kick defaults") : path) + ": " + e.what());
  }
  return def;
}

} // namespace touchline::robot
