#pragma once
// A team's behaviour library (robot_api/plugin.hpp), loaded by path: robot_shim and
// touchline_match --behaviour-plugin PATH --behaviour NAME. Reads the library's entry point;
// writes nothing. A library once loaded stays loaded for the process's life: the behaviours
// it made run its code until the end.
#include <memory>
#include <string>

#include "touchline/robot_api/behaviour.hpp"
#include "touchline/robot_api/plugin.hpp"

namespace touchline::apps {

/// The behaviour request.name made by the library at `path`. Throws behaviour::BehaviourError
/// with one line naming `path`: no such file, not a loadable library, no entry point, built
/// against another robot API (ABI version or sizes), or the factory refused the name or a
/// parameter (its own line) or made nothing.
std::unique_ptr<api::Behaviour> make_plugin_behaviour(const std::string& path, const api::PluginRequest& request);

} // namespace touchline::apps
