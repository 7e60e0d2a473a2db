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
    EXPECT_STREQ(e.what(), "unknown walk engine 'moonwalk' (walkcycle, nao-joints)");
  }
}
