// A team's behaviour library loaded by path (apps::make_plugin_behaviour): its behaviours are
// made with the request's name, params, robot and data directory; every way a library can be
// wrong is one line naming it (robot_shim and touchline_match print it and exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "touchline/apps/behaviour_plugin.hpp"
#include "touchline/behaviour/registry.hpp"

namespace touchline::apps {
namespace {

api::PluginRequest request(const std::string& name, std::map<std::string, std::string> params = {}) {
  api::PluginRequest r;
  r.name = name;
  r.params = std::move(params);
  r.team = 1;
  r.player = 3;
  r.data_dir = std::filesystem::temp_directory_path().string();
  return r;
}

/// The one line make_plugin_behaviour throws for `path` and `r`.
std::string error_of(const std::string& path, const api::PluginRequest& r) {
  try {
    make_plugin_behaviour(path, r);
  } catch (const behaviour::BehaviourError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "no error for " << path << " " << r.name;
  return "";
}

TEST(BehaviourPlugin, MakesTheNamedBehaviourWithItsParamsForTheRobot) {
  const auto walk = make_plugin_behaviour(TOUCHLINE_FIXTURE_PLUGIN, request("Walk", {{"forward", "150"}}));
  const api::ActionCommand::All act = walk->tick(api::Blackboard{});
  EXPECT_EQ(act.body.actionType, api::ActionCommand::ActionType::WALK);
  EXPECT_FLOAT_EQ(act.body.forward, 150.f);
  EXPECT_EQ(act.leds.chest, 1 * 16 + 3);
  // Loaded once, made again for another robot.
  EXPECT_NE(make_plugin_behaviour(TOUCHLINE_FIXTURE_PLUGIN, request("Walk")), nullptr);
}

TEST(BehaviourPlugin, TheLibraryLooksInTheRequestsDataDirectory) {
  const auto dir = std::filesystem::temp_directory_path() / "touchline_test_behaviour_plugin";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "table.bin") << "x";
  auto r = request("NeedsData", {{"file", "table.bin"}});
  r.data_dir = dir.string();
  EXPECT_NE(make_plugin_behaviour(TOUCHLINE_FIXTURE_PLUGIN, r), nullptr);
  r.data_dir = (dir / "elsewhere").string();
  EXPECT_NE(error_of(TOUCHLINE_FIXTURE_PLUGIN, r).find("NeedsData: no " + (dir / "elsewhere" / "table.bin").string()),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(BehaviourPlugin, ANameTheLibraryRefusesIsItsOwnLine) {
  EXPECT_EQ(error_of(TOUCHLINE_FIXTURE_PLUGIN, request("Nope")),
            std::string("--behaviour-plugin ") + TOUCHLINE_FIXTURE_PLUGIN + ": unknown behaviour 'Nope'");
  EXPECT_EQ(error_of(TOUCHLINE_FIXTURE_PLUGIN, request("Nothing")),
            std::string("--behaviour-plugin ") + TOUCHLINE_FIXTURE_PLUGIN + ": made nothing for 'Nothing'");
}

TEST(BehaviourPlugin, AMissingFileIsRefused) {
  EXPECT_EQ(error_of("/nonexistent/libteam.so", request("Walk")),
            "--behaviour-plugin /nonexistent/libteam.so: no such file");
}

TEST(BehaviourPlugin, AFileThatIsNoLibraryIsRefused) {
  const auto path = std::filesystem::temp_directory_path() / "touchline_test_not_a_library.so";
  std::ofstream(path) << "not a library\n";
  EXPECT_NE(error_of(path.string(), request("Walk")).find(path.string() + ": cannot load: "), std::string::npos);
  std::filesystem::remove(path);
}

TEST(BehaviourPlugin, ALibraryWithoutTheEntryPointIsRefused) {
  EXPECT_NE(error_of(TOUCHLINE_NO_ENTRY_PLUGIN, request("Walk")).find(": no entry point touchline_behaviour_plugin"),
            std::string::npos);
}

TEST(BehaviourPlugin, ALibraryOfAnotherAbiIsRefused) {
  EXPECT_NE(error_of(TOUCHLINE_WRONG_ABI_PLUGIN, request("Walk"))
                .find(": built for plugin ABI 999, this program plays ABI " + std::to_string(api::kPluginAbiVersion)),
            std::string::npos);
}

TEST(BehaviourPlugin, ALibraryBuiltAgainstOtherHeadersIsRefused) {
  const auto blackboard_bytes = std::to_string(sizeof(api::Blackboard));
  EXPECT_NE(error_of(TOUCHLINE_WRONG_LAYOUT_PLUGIN, request("Walk"))
                .find(": built against other robot API headers (Blackboard " +
                      std::to_string(sizeof(api::Blackboard) + 8) + " bytes there, " + blackboard_bytes + " here)"),
            std::string::npos);
}

} // namespace
} // namespace touchline::apps
