#pragma once
// The robot's data directory: where robot code finds its files (learned policies, tables),
// as rUNSWift's code reads /home/nao/data on the robot. Behaviour code asks for
// data_path("policies/go_to_pose.policy"); robot_shim sets the directory (--data-dir), and
// Python sees the same directory through robot.data_path(name).
#include <filesystem>
#include <string>

// The build passes the source tree's config/ (robot_api/CMakeLists.txt); a compile
// without it gets the robot's own place.
#ifndef TOUCHLINE_DEFAULT_DATA_DIR
#define TOUCHLINE_DEFAULT_DATA_DIR "/home/nao/data"
#endif

namespace touchline::api {

namespace detail {
inline std::string& data_dir_storage() {
  static std::string directory = TOUCHLINE_DEFAULT_DATA_DIR;
  return directory;
}
} // namespace detail

/// The data directory now in force.
inline const std::string& data_dir() { return detail::data_dir_storage(); }

/// Sets the data directory (robot_shim does, from --data-dir; tests and tools may).
inline void set_data_dir(const std::string& directory) { detail::data_dir_storage() = directory; }

/// The path of `name` (relative, e.g. "policies/go_to_pose.policy") in the data
/// directory; an absolute name is returned as it is.
inline std::string data_path(const std::string& name) {
  return (std::filesystem::path(data_dir()) / name).string();
}

} // namespace touchline::api
