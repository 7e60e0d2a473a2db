// The programs' log: "NAME: message" lines on stderr, the form tools and tests read, and
// --log-level choosing which lines appear.
#include <gtest/gtest.h>

#include <string>

#include <boost/program_options/errors.hpp>

#include "touchline/apps/program_log.hpp"

using namespace touchline;

namespace {

std::string said(const std::string& level) {
  const auto log = apps::program_log("sim_world");
  apps::set_log_level(*log, level);
  testing::internal::CaptureStderr();
  log->debug("frame {} sent again", 12);
  log->info("kick-off with {} robots", 8);
  log->warn("ignored malformed message: {}", "TL_ACT_0_1");
  log->error("no robots joined");
  return testing::internal::GetCapturedStderr();
}

} // namespace

TEST(ProgramLog, InfoByDefaultEachLineNamedByItsProgram) {
  EXPECT_EQ(said("info"), "sim_world: kick-off with 8 robots\n"
                          "sim_world: ignored malformed message: TL_ACT_0_1\n"
                          "sim_world: no robots joined\n");
}

TEST(ProgramLog, TheLevelChoosesTheLines) {
  EXPECT_EQ(said("debug"), "sim_world: frame 12 sent again\n"
                           "sim_world: kick-off with 8 robots\n"
                           "sim_world: ignored malformed message: TL_ACT_0_1\n"
                           "sim_world: no robots joined\n");
  EXPECT_EQ(said("warning"), "sim_world: ignored malformed message: TL_ACT_0_1\n"
                             "sim_world: no robots joined\n");
  EXPECT_EQ(said("error"), "sim_world: no robots joined\n");
  EXPECT_EQ(said("off"), "");
}

TEST(ProgramLog, AnUnknownLevelIsRefusedWithTheLevelsNamed) {
  const auto log = apps::program_log("robot_shim");
  try {
    apps::set_log_level(*log, "loud");
    FAIL() << "loud was taken as a level";
  } catch (const boost::program_options::error& e) {
    EXPECT_EQ(std::string(e.what()), std::string("--log-level loud: not a level (") + apps::kLogLevels + ")");
  }
  EXPECT_EQ(log->level(), spdlog::level::info); // left as it was
}
