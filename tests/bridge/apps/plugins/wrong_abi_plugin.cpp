// A library built for another plugin ABI: its entry point reports version 999.
#include "touchline/robot_api/plugin.hpp"

extern "C" __attribute__((visibility("default"))) const touchline::api::PluginInfo* touchline_behaviour_plugin() {
  static touchline::api::PluginInfo info = touchline::api::plugin_info(nullptr);
  info.abi_version = 999;
  return &info;
}
