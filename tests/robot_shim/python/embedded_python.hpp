#pragma once
// What the in-process tests of the embedded Python runtime share: one interpreter for the
// test process (as robot_shim holds one), a temp folder for behaviour files, copying a
// fixture in as an edit the file watcher sees, and counting lines in a captured log.
#include <gtest/gtest.h>
#include <pybind11/embed.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace touchline::testing_support {

/// One interpreter for the whole test process, started with these environment variables
/// unset (what the runtime must not depend on the user's environment for).
// Hidden, as pybind11's own types are (it holds one).
class __attribute__((visibility("hidden"))) EmbeddedPython : public ::testing::Environment {
 public:
  explicit EmbeddedPython(std::vector<std::string> unset) : unset_(std::move(unset)) {}
  void SetUp() override {
    for (const std::string& name : unset_) unsetenv(name.c_str());
    guard_ = std::make_unique<pybind11::scoped_interpreter>(false, 0, nullptr, false);
  }
  void TearDown() override { guard_.reset(); }

 private:
  std::vector<std::string> unset_;
  std::unique_ptr<pybind11::scoped_interpreter> guard_;
};

/// A new empty folder under the temp directory ("" if none could be made).
inline std::filesystem::path make_temp_dir(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  return mkdtemp(pattern.data()) ? std::filesystem::path(pattern) : std::filesystem::path();
}

/// Copies `source` over `target`. An edit must be visible to the watcher, as any real edit
/// is some time later: if the copy happens to keep the file's mtime (same clock tick), its
/// mtime moves on by 1 ms.
inline void copy_as_edit(const std::filesystem::path& source, const std::filesystem::path& target) {
  namespace fs = std::filesystem;
  const bool existed = fs::exists(target);
  const auto old_time = existed ? fs::last_write_time(target) : fs::file_time_type{};
  fs::copy_file(source, target, fs::copy_options::overwrite_existing);
  if (existed && fs::last_write_time(target) <= old_time)
    fs::last_write_time(target, old_time + std::chrono::milliseconds(1));
}

/// How often `needle` occurs in `text`.
inline int count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

} // namespace touchline::testing_support
