#pragma once
// A behaviour library of a team's own: built outside this tree against the installed robot
// API (find_package(Touchline), target touchline::robot_api) and played by robot_shim or
// touchline_match with --behaviour-plugin PATH --behaviour NAME. The library has one entry
// point, defined by TOUCHLINE_BEHAVIOUR_PLUGIN(factory); the program checks that the library
// was built against the same robot API (the ABI version and the sizes of what crosses)
// before it makes a behaviour, so a stale library is a one-line refusal, not a crash.
//
// What crosses is C++ (api::Behaviour, Blackboard, ActionCommand), so build the library with
// the same compiler family and standard library as the programs (g++ / libstdc++ of the
// same Debian release), as any C++ plugin must be.
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "touchline/robot_api/behaviour.hpp"
#include "touchline/robot_api/data.hpp"

namespace touchline::api {

/// Raised with every change to what crosses between program and library: Behaviour,
/// Blackboard, ActionCommand, PluginRequest or PluginInfo.
inline constexpr uint32_t kPluginAbiVersion = 1;

/// The name of the library's entry point (extern "C", made by TOUCHLINE_BEHAVIOUR_PLUGIN).
inline constexpr const char* kPluginEntryPoint = "touchline_behaviour_plugin";

/// What the program asks the library for: one robot's behaviour.
struct PluginRequest {
  std::string name;                          ///< --behaviour NAME
  std::map<std::string, std::string> params; ///< --param key=value, strings as given
  int team = 0;                              ///< 0 or 1
  int player = 1;                            ///< 1..7
  std::string data_dir;                      ///< --data-dir: api::data_path looks there in the library too
};

/// The library's factory: the behaviour request.name. Throws std::invalid_argument with one
/// line (an unknown name, a bad parameter): the program prints it and exits 2.
using PluginFactory = std::unique_ptr<Behaviour> (*)(const PluginRequest& request);

/// What the entry point returns. abi_version stays the first member in every version, so
/// any program can read it.
struct PluginInfo {
  uint32_t abi_version;      ///< kPluginAbiVersion the library was built with
  uint32_t blackboard_bytes; ///< sizeof(Blackboard) there
  uint32_t action_bytes;     ///< sizeof(ActionCommand::All) there
  uint32_t request_bytes;    ///< sizeof(PluginRequest) there (std::string's ABI included)
  PluginFactory make;        ///< the factory (data directory set first)
};

/// This side's sizes, as a library built now fills them in.
inline PluginInfo plugin_info(PluginFactory make) {
  return {kPluginAbiVersion, static_cast<uint32_t>(sizeof(Blackboard)),
          static_cast<uint32_t>(sizeof(ActionCommand::All)), static_cast<uint32_t>(sizeof(PluginRequest)), make};
}

namespace detail {
/// The library keeps its own copy of the data directory (data.hpp's storage is per shared
/// object): set it from the request before the factory, which may load its data.
template <PluginFactory Factory>
std::unique_ptr<Behaviour> make_in_plugin(const PluginRequest& request) {
  set_data_dir(request.data_dir);
  return Factory(request);
}
} // namespace detail

} // namespace touchline::api

/// Defines the library's entry point for `factory`, a function
/// std::unique_ptr<touchline::api::Behaviour>(const touchline::api::PluginRequest&).
/// Use once, at namespace scope, in one source file of the library.
#define TOUCHLINE_BEHAVIOUR_PLUGIN(factory)                                                          \
  extern "C" __attribute__((visibility("default"))) const ::touchline::api::PluginInfo*             \
  touchline_behaviour_plugin() {                                                                    \
    static const ::touchline::api::PluginInfo info =                                                \
        ::touchline::api::plugin_info(&::touchline::api::detail::make_in_plugin<factory>);          \
    return &info;                                                                                   \
  }
