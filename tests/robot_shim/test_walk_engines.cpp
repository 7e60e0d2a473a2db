#include "touchline/robot/walk_engines.hpp"

#include <gtest/gtest.h>

#include "touchline/ini.hpp"

using namespace touchline;
using namespace touchline::robot;

TEST(WalkEngines, EachNameMakesItsEngine) {
  for (const std::string& name : walk_engine_names()) {
    WalkEngineDef def;
    def.name = name;
    const auto engine = make_walk_engine(def, WalkDef{}, KickDef{});
    ASSERT_TRUE(engine);
    EXPECT_EQ(engine->name(), name);
    EXPECT_GT(engine->period_us(), 0);
  }
  EXPECT_EQ(walk_engine_names().front(), "walkcycle");
  EXPECT_EQ(WalkEngineDef{}.name, "walkcycle");
}

TEST(WalkEngines, AnUnknownNameIsOneLineListingTheKnownOnes) {
  WalkEngineDef def;
  def.name = "moonwalk";
  try {
    make_walk_engine(def, WalkDef{}, KickDef{});
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    std::string known;
    for (const std::string& name : walk_engine_names()) known += (known.empty() ? "" : ", ") + name;
    EXPECT_EQ(std::string(e.what()), "unknown walk engine 'moonwalk' (" + known + ")");
    EXPECT_EQ(known.rfind("walkcycle, nao-joints", 0), 0u); // (and runswift in a build with their code)
  }
}
