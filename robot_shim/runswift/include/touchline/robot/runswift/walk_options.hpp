#pragma once
// The option values rUNSWift's walk reads (Walk2014Generator::readOptions): our own struct
// with the defaults their options code gives, overridable from their own INI-style .cfg
// files (their image's home/nao/data/runswift.cfg, configs/body/<body>.cfg, ...), read with
// Boost.ProgramOptions through touchline::IniSchema. Part of the compatibility library: no
// header of theirs here.
#include <string>
#include <vector>

#include <boost/program_options/variables_map.hpp>

namespace touchline::robot::runswift {

/// Their walk's options: each field is the key in the comment, in the unit it names.
struct WalkOptions {
  // [motion]: the sagittal balance controllers.
  float gyro_kp = 0.07f;          ///< motion.KpGyro: ankle pitch per filtered gyro Y, s
  float gyro_kd = 0.0003934f;     ///< motion.KdGyro: derivative gain, s^2
  float angle_kp = 0.2f;          ///< motion.KpAngle: hip pitch per torso pitch error
  float angle_ki = 0.05f;         ///< motion.KiAngle: integral gain, 1/s
  float angle_kd = 0.008f;        ///< motion.KdAngle: derivative gain, s
  // [kick]: lean and stability.
  float kick_lean_deg = 20.5f;             ///< kick.lean: sideways lean onto the support foot
  bool lean_offset_l_varied = false;       ///< kick.leanOffsetLVaried: use the inner/mid/outer offsets
  float lean_offset_l_deg = 0;             ///< kick.leanOffsetL
  float lean_offset_l_inner_deg = 0;       ///< kick.leanOffsetLInner
  float lean_offset_l_mid_deg = 0;         ///< kick.leanOffsetLMid
  float lean_offset_l_outer_deg = 0;       ///< kick.leanOffsetLOuter
  bool lean_offset_r_varied = false;       ///< kick.leanOffsetRVaried
  float lean_offset_r_deg = 0;             ///< kick.leanOffsetR
  float lean_offset_r_inner_deg = 0;       ///< kick.leanOffsetRInner
  float lean_offset_r_mid_deg = 0;         ///< kick.leanOffsetRMid
  float lean_offset_r_outer_deg = 0;       ///< kick.leanOffsetROuter
  int stable_frames = 3;                   ///< kick.stableNumFrames: motion ticks stable before a kick
  float stable_angle_x_deg = 5;            ///< kick.stableAngleX
  float extra_stable_angle_x_deg = 4;      ///< kick.extraStableAngleX
  float extra_stable_gyro_x_deg_s = 5;     ///< kick.extraStableGyroscopeX
  float gyro_x_onto_support_deg_s = 5;     ///< kick.kickGyroscopeXOntoSupportFootThresh
  float gyro_x_away_from_support_deg_s = 30; ///< kick.kickGyroscopeXAwayFromSupportFootThresh
  // [calibration]
  bool kick_calibration = false;           ///< calibration.kick: their kick calibration mode
};

/// Their defaults, then each file of `paths` in order: a key a later file sets wins (give
/// the general file first, e.g. runswift.cfg then configs/body/robot1.cfg). Keys of theirs
/// that the walk does not read are skipped. Throws touchline::ConfigError, one line naming
/// the path and the fault ("<path>: kick.lean must be a finite number (got 'x')").
WalkOptions load_walk_options(const std::vector<std::string>& paths);

/// The options as the variables_map their readOptions reads (their key names and types).
boost::program_options::variables_map to_variables_map(const WalkOptions& options);

} // namespace touchline::robot::runswift
