#include "touchline/apps/behaviour_plugin.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>

#include "touchline/behaviour/registry.hpp"

namespace touchline::apps {

namespace {

using behaviour::BehaviourError;
using EntryPoint = const api::PluginInfo* (*)();

/// dlerror's text on one line (it may name the file again, or hold a newline).
std::string last_dl_error() {
  const char* text = dlerror();
  std::string line = text ? text : "unknown error";
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return line;
}

/// The library's checked entry, loaded once per path (every robot of touchline_match that
/// names it shares it). Never unloaded.
const api::PluginInfo& load(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, const api::PluginInfo*> loaded;
  const std::lock_guard<std::mutex> lock(mutex);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw BehaviourError("--behaviour-plugin " + path + ": no such file");
  // Absolute: a name without a slash would be looked for on the library path instead.
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  if (const auto it = loaded.find(absolute); it != loaded.end()) return *it->second;
  // RTLD_LOCAL: two libraries may each have their own helpers of the same name.
  void* handle = dlopen(absolute.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw BehaviourError("--behaviour-plugin " + path + ": cannot load: " + last_dl_error());
  dlerror();
  void* symbol = dlsym(handle, api::kPluginEntryPoint);
  if (!symbol)
    throw BehaviourError("--behaviour-plugin " + path + ": no entry point " + api::kPluginEntryPoint +
                         " (define it with TOUCHLINE_BEHAVIOUR_PLUGIN, robot_api/plugin.hpp)");
  const api::PluginInfo* info = reinterpret_cast<EntryPoint>(symbol)();
  if (!info) throw BehaviourError("--behaviour-plugin " + path + ": its entry point returned nothing");
  if (info->abi_version != api::kPluginAbiVersion)
    throw BehaviourError("--behaviour-plugin " + path + ": built for plugin ABI " + std::to_string(info->abi_version) +
                         ", this program plays ABI " + std::to_string(api::kPluginAbiVersion) +
                         ": rebuild it against this Touchline");
  const api::PluginInfo here = api::plugin_info(nullptr);
  if (info->blackboard_bytes != here.blackboard_bytes || info->action_bytes != here.action_bytes ||
      info->request_bytes != here.request_bytes)
    throw BehaviourError("--behaviour-plugin " + path + ": built against other robot API headers (Blackboard " +
                         std::to_string(info->blackboard_bytes) + " bytes there, " +
                         std::to_string(here.blackboard_bytes) + " here): rebuild it against this Touchline");
  if (!info->make) throw BehaviourError("--behaviour-plugin " + path + ": no factory");
  loaded[absolute] = info; // the handle is kept open on purpose: see the header
  return *info;
}

} // namespace

std::unique_ptr<api::Behaviour> make_plugin_behaviour(const std::string& path, const api::PluginRequest& request) {
  const api::PluginInfo& plugin = load(path);
  std::unique_ptr<api::Behaviour> made;
  try {
    made = plugin.make(request);
  } catch (const std::exception& e) {
    throw BehaviourError("--behaviour-plugin " + path + ": " + e.what());
  } catch (...) {
    throw BehaviourError("--behaviour-plugin " + path + ": its factory failed for '" + request.name + "'");
  }
  if (!made) throw BehaviourError("--behaviour-plugin " + path + ": made nothing for '" + request.name + "'");
  return made;
}

} // namespace touchline::apps
