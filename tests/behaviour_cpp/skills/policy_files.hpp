#pragma once
// Policy files for the learned-walker tests: the small deterministic test policy of
// tests/behaviour_py/policy_files.py (same text, same known greedy actions), and a robot
// data directory holding it.
//
// The test policy: 2 tilings of 4 x 8 x 8 tiles, three actions (forward 300 mm/s, turn left
// 1 rad/s, turn right 1 rad/s). Each cell's weights depend on its bearing tile ib alone:
// forward 1 when ib is 3 or 4 (the target about ahead), left 0.5 when ib >= 5, right 0.5
// when ib <= 2.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "touchline/robot_api/data.hpp"

namespace touchline::behaviour::test {

inline double bearingWeight(int ib, int action) {
  if (action == 0) return ib == 3 || ib == 4 ? 1.0 : 0.0;
  if (action == 1) return ib >= 5 ? 0.5 : 0.0;
  return ib <= 2 ? 0.5 : 0.0;
}

/// The test policy's file text with weight(ib, action) for every cell.
inline std::string policyText(const std::function<double(int, int)>& weight = bearingWeight) {
  constexpr int tilings = 2, tilesU = 4, tilesB = 8, tilesH = 8, actions = 3;
  std::string text =
      "touchline-policy 1\n# the go-to-pose test policy (tests/behaviour_py/policy_files.py)\nfeatures polar-log\n"
      "distance_scale_mm 100\nmax_distance_mm 12000\ntilings 2\ntiles 4 8 8\nsuccess_distance_mm 50\n"
      "success_heading_rad 0.17453\nactions 3\naction 300 0 0\naction 0 0 1\naction 0 0 -1\nweights 1920\n";
  int written = 0;
  char number[32];
  for (int k = 0; k < tilings; ++k)
    for (int iu = 0; iu <= tilesU; ++iu)
      for (int ib = 0; ib < tilesB; ++ib)
        for (int ih = 0; ih < tilesH; ++ih)
          for (int a = 0; a < actions; ++a) {
            std::snprintf(number, sizeof number, "%.9g", weight(ib, a));
            text += number;
            text += ++written % 8 == 0 ? "\n" : " ";
          }
  return text;
}

/// Writes `text` to path, making its folder.
inline void writePolicy(const std::filesystem::path& path, const std::string& text = policyText()) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

/// A fresh robot data directory holding the test policy at policies/go_to_pose.policy, in
/// force while this lives.
class TestDataDir {
 public:
  TestDataDir() : previous_(api::data_dir()) {
    static int made = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("touchline_data_" + std::to_string(::getpid()) + "_" + std::to_string(made++));
    std::filesystem::remove_all(path_);
    writePolicy(path_ / "policies" / "go_to_pose.policy");
    api::set_data_dir(path_.string());
  }
  ~TestDataDir() {
    api::set_data_dir(previous_);
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TestDataDir(const TestDataDir&) = delete;
  TestDataDir& operator=(const TestDataDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::string previous_;
  std::filesystem::path path_;
};

} // namespace touchline::behaviour::test
