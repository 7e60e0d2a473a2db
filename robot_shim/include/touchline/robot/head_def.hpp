#pragma once
// HeadDef: the head that points the camera (the camera's view itself is the world's
// [camera]): its joint limits and speed, the [head] section of config/head.ini.
#include <string>

namespace touchline::robot {

/// Head joint limits (Nao V6: HeadYaw +-2.0857 rad, HeadPitch -0.672 .. 0.5149 rad) and speed.
struct HeadDef {
  float max_yaw_rad = 2.08f;       ///< either side
  float min_pitch_rad = -0.67f;    ///< up (negative)
  float max_pitch_rad = 0.51f;     ///< down
  float max_speed_rad_s = 4.0f;    ///< at yawSpeed/pitchSpeed = 1
};

/// [head] of the INI file at `path` ("" for the built-in head); keys it leaves out keep
/// their default. Throws ConfigError, one line naming the file and the key
/// ("config/head.ini: head.max_yaw_rad must be in [0, 3.1416] (got 4)").
HeadDef load_head_def(const std::string& path);

} // namespace touchline::robot
