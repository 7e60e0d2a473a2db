// A library of the same plugin ABI version built against other robot API headers: its
// Blackboard is 8 bytes larger (a member added without raising kPluginAbiVersion).
#include "touchline/robot_api/plugin.hpp"

extern "C" __attribute__((visibility("default"))) const touchline::api::PluginInfo* touchline_behaviour_plugin() {
  static touchline::api::PluginInfo info = touchline::api::plugin_info(nullptr);
  info.blackboard_bytes += 8;
  return &info;
}
