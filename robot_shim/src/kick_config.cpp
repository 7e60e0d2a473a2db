#include <sstream>
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

/// Throws unless `ok`, naming the file and key: "config/kick.ini: kick.prepare_s must be
/// >= 0 (got -1)".
void require(bool ok, const std::string& path, const std::string& key, const char* rule,
             float got) {
  if (ok) return;
  std::ostringstream message;
  message << (path.empty() ? std::string("kick defaults") : path) << ": " << key << ' ' << rule
          << " (got " << got << ')';
  throw ConfigError(message.str());
}

void validate(const SwingDef& d, const std::string& section, const std::string& path) {
  auto check = [&](bool ok, const char* key, const char* rule, float got) {
    require(ok, path, section + "." + key, rule, got);
  };
  check(d.prepare_s >= 0, "prepare_s", "must be >= 0", d.prepare_s);
  check(d.backswing_mm >= 0, "backswing_mm", "must be >= 0", d.backswing_mm);
  check(d.swing_length_mm > 0, "swing_length_mm", "must be > 0", d.swing_length_mm);
  check(d.peak_speed_mm_s > 0 && d.peak_speed_mm_s <= kMaxFootSpeed_mm_s, "peak_speed_mm_s",
        "must be in (0, 3000]", d.peak_speed_mm_s);
  check(d.min_power > 0 && d.min_power <= 1, "min_power", "must be in (0, 1]", d.min_power);
  check(d.reposition_speed_mm_s > 0 && d.reposition_speed_mm_s <= kMaxFootSpeed_mm_s,
        "reposition_speed_mm_s", "must be in (0, 3000]", d.reposition_speed_mm_s);
  check(d.aim_speed_rad_s > 0, "aim_speed_rad_s", "must be > 0", d.aim_speed_rad_s);
  check(d.max_bend_rad >= 0 && d.max_bend_rad <= kMaxBend_rad, "max_bend_rad",
        "must be in [0, 1]", d.max_bend_rad);
  check(d.recover_s >= 0, "recover_s", "must be >= 0", d.recover_s);
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
  validate(def.kick, "kick", path);
  validate(def.dribble, "dribble", path);
  return def;
}

} // namespace touchline::robot
