// install_dirs: an installed program finds its prefix's share/touchline/ beside its bin/; a
// program without one there (a build tree's bin/) gets "" and keeps the source tree's folders.
#include "touchline/apps/install_dirs.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using touchline::apps::installed_share_dir;

namespace {

fs::path fresh_prefix(const std::string& name) {
  const fs::path prefix = fs::path(::testing::TempDir()) / name;
  fs::remove_all(prefix);
  fs::create_directories(prefix / "bin");
  std::ofstream(prefix / "bin" / "robot_shim") << "";
  return prefix;
}

} // namespace

TEST(InstallDirs, AProgramInAPrefixFindsItsShareFolder) {
  const fs::path prefix = fresh_prefix("touchline_install_dirs_full");
  fs::create_directories(prefix / "share" / "touchline" / "behaviour_py");
  fs::create_directories(prefix / "share" / "touchline" / "config");
  EXPECT_EQ(installed_share_dir((prefix / "bin" / "robot_shim").string()), (prefix / "share" / "touchline").string());
}

TEST(InstallDirs, ABuildTreesProgramHasNone) {
  const fs::path prefix = fresh_prefix("touchline_install_dirs_none");
  EXPECT_EQ(installed_share_dir((prefix / "bin" / "robot_shim").string()), "");
  // Half a share folder (no behaviour_py/) is not an installed one either.
  fs::create_directories(prefix / "share" / "touchline" / "config");
  EXPECT_EQ(installed_share_dir((prefix / "bin" / "robot_shim").string()), "");
}

TEST(InstallDirs, ThisTestProgramRunsFromABuildTree) {
  EXPECT_EQ(installed_share_dir(), "");
}
