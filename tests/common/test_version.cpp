// --version: the one version (the VERSION file at the root, through CMake) and its line.
#include "touchline/version.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace po = boost::program_options;

namespace touchline {
namespace {

TEST(Version, IsTheVersionFile) {
  std::ifstream in(std::string(TOUCHLINE_SOURCE_DIR) + "/VERSION");
  std::string file;
  std::getline(in, file);
  EXPECT_EQ(version(), file);
}

TEST(Version, PrintsTheProgramAndVersionOnlyWhenAsked) {
  po::options_description options;
  options.add_options()("version", kVersionHelp);
  const char* with[] = {"program", "--version"};
  const char* without[] = {"program"};
  po::variables_map asked, not_asked;
  po::store(po::parse_command_line(2, with, options), asked);
  po::store(po::parse_command_line(1, without, options), not_asked);
  std::ostringstream out;
  auto* old = std::cout.rdbuf(out.rdbuf());
  const bool printed = version_requested(asked, "sim_world");
  const bool silent = version_requested(not_asked, "sim_world");
  std::cout.rdbuf(old);
  EXPECT_TRUE(printed);
  EXPECT_FALSE(silent);
  EXPECT_EQ(out.str(), std::string("sim_world ") + version() + "\n");
}

} // namespace
} // namespace touchline
