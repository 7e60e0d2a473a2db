#include "touchline/robot/runswift/walk_options.hpp"

#include <boost/any.hpp>
#include <boost/program_options/variables_map.hpp>

#include "touchline/ini.hpp"

namespace touchline::robot::runswift {

namespace po = boost::program_options;

namespace {

/// Every key their readOptions reads, bound to its field.
IniSchema schema_for(WalkOptions* o) {
  IniSchema schema("rUNSWift walk options");
  schema.bind("motion.KpGyro", &o->gyro_kp, "gyro PD controller, proportional")
      .bind("motion.KdGyro", &o->gyro_kd, "gyro PD controller, derivative")
      .bind("motion.KpAngle", &o->angle_kp, "angle PID controller, proportional")
      .bind("motion.KiAngle", &o->angle_ki, "angle PID controller, integral")
      .bind("motion.KdAngle", &o->angle_kd, "angle PID controller, derivative")
      .bind("kick.lean", &o->kick_lean_deg, "kick lean, degrees")
      .bind("kick.leanOffsetLVaried", &o->lean_offset_l_varied, "left kick: vary the lean offset with the ball")
      .bind("kick.leanOffsetL", &o->lean_offset_l_deg, "left kick lean offset, degrees")
      .bind("kick.leanOffsetLInner", &o->lean_offset_l_inner_deg, "left kick, ball near the centre line")
      .bind("kick.leanOffsetLMid", &o->lean_offset_l_mid_deg, "left kick, ball moderately far")
      .bind("kick.leanOffsetLOuter", &o->lean_offset_l_outer_deg, "left kick, ball far")
      .bind("kick.leanOffsetRVaried", &o->lean_offset_r_varied, "right kick: vary the lean offset with the ball")
      .bind("kick.leanOffsetR", &o->lean_offset_r_deg, "right kick lean offset, degrees")
      .bind("kick.leanOffsetRInner", &o->lean_offset_r_inner_deg, "right kick, ball near the centre line")
      .bind("kick.leanOffsetRMid", &o->lean_offset_r_mid_deg, "right kick, ball moderately far")
      .bind("kick.leanOffsetROuter", &o->lean_offset_r_outer_deg, "right kick, ball far")
      .bind("kick.stableNumFrames", &o->stable_frames, "motion ticks stable before kicking")
      .bind("kick.stableAngleX", &o->stable_angle_x_deg, "angle X stable before kicking, degrees")
      .bind("kick.extraStableAngleX", &o->extra_stable_angle_x_deg, "angle X extra stable, degrees")
      .bind("kick.extraStableGyroscopeX", &o->extra_stable_gyro_x_deg_s, "gyro X extra stable, degrees/s")
      .bind("kick.kickGyroscopeXOntoSupportFootThresh", &o->gyro_x_onto_support_deg_s,
            "gyro X rocking onto the support foot, degrees/s")
      .bind("kick.kickGyroscopeXAwayFromSupportFootThresh", &o->gyro_x_away_from_support_deg_s,
            "gyro X rocking away from the support foot, degrees/s")
      .bind("calibration.kick", &o->kick_calibration, "kick calibration mode");
  return schema;
}

template <typename T>
void put(po::variables_map& vm, const char* key, T value) {
  vm.emplace(key, po::variable_value(boost::any(value), false));
}

} // namespace

WalkOptions load_walk_options(const std::vector<std::string>& paths) {
  WalkOptions options;
  const IniSchema schema = schema_for(&options);
  for (const auto& path : paths) {
    schema.read_file(path, /*ignore_unknown=*/true); // their files hold every other module's keys too
    try {
      require_count("kick.stableNumFrames", options.stable_frames, 0, 10000);
    } catch (const ConfigError& e) {
      throw ConfigError(path + ": " + e.what());
    }
  }
  return options;
}

po::variables_map to_variables_map(const WalkOptions& o) {
  po::variables_map vm;
  put(vm, "motion.KpGyro", o.gyro_kp);
  put(vm, "motion.KdGyro", o.gyro_kd);
  put(vm, "motion.KpAngle", o.angle_kp);
  put(vm, "motion.KiAngle", o.angle_ki);
  put(vm, "motion.KdAngle", o.angle_kd);
  put(vm, "kick.lean", o.kick_lean_deg);
  put(vm, "kick.leanOffsetLVaried", o.lean_offset_l_varied);
  put(vm, "kick.leanOffsetL", o.lean_offset_l_deg);
  put(vm, "kick.leanOffsetLInner", o.lean_offset_l_inner_deg);
  put(vm, "kick.leanOffsetLMid", o.lean_offset_l_mid_deg);
  put(vm, "kick.leanOffsetLOuter", o.lean_offset_l_outer_deg);
  put(vm, "kick.leanOffsetRVaried", o.lean_offset_r_varied);
  put(vm, "kick.leanOffsetR", o.lean_offset_r_deg);
  put(vm, "kick.leanOffsetRInner", o.lean_offset_r_inner_deg);
  put(vm, "kick.leanOffsetRMid", o.lean_offset_r_mid_deg);
  put(vm, "kick.leanOffsetROuter", o.lean_offset_r_outer_deg);
  put(vm, "kick.stableNumFrames", o.stable_frames);
  put(vm, "kick.stableAngleX", o.stable_angle_x_deg);
  put(vm, "kick.extraStableAngleX", o.extra_stable_angle_x_deg);
  put(vm, "kick.extraStableGyroscopeX", o.extra_stable_gyro_x_deg_s);
  put(vm, "kick.kickGyroscopeXOntoSupportFootThresh", o.gyro_x_onto_support_deg_s);
  put(vm, "kick.kickGyroscopeXAwayFromSupportFootThresh", o.gyro_x_away_from_support_deg_s);
  put(vm, "calibration.kick", o.kick_calibration);
  return vm;
}

} // namespace touchline::robot::runswift
