// load_head_def: [head] of config/head.ini, every number bounded, one line naming the file.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "touchline/ini.hpp"
#include "touchline/robot/head_def.hpp"

namespace touchline::robot {
namespace {

std::string error_for(const std::string& text) {
  const std::string path = ::testing::TempDir() + "head_config.ini";
  std::ofstream(path) << text;
  try {
    load_head_def(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(HeadConfig, NoFileIsTheBuiltInHead) {
  const HeadDef def = load_head_def("");
  EXPECT_FLOAT_EQ(def.max_yaw_rad, HeadDef{}.max_yaw_rad);
  EXPECT_FLOAT_EQ(def.max_speed_rad_s, HeadDef{}.max_speed_rad_s);
}

TEST(HeadConfig, EveryNumberIsBoundedAndNamed) {
  EXPECT_EQ(error_for("[head]\nmax_yaw_rad = 1.5\nmax_speed_rad_s = 8\n"), "");
  for (const auto& [text, what] : {
           std::pair{"[head]\nmax_yaw_rad = 4\n", "head.max_yaw_rad must be in [0, 3.1416] (got 4)"},
           std::pair{"[head]\nmax_pitch_rad = -0.1\n", "head.max_pitch_rad must be in [0, 3.1416] (got -0.1)"},
           std::pair{"[head]\nmin_pitch_rad = 0.3\n", "head.min_pitch_rad must be in [-3.1416, 0] (got 0.3)"},
           std::pair{"[head]\nmax_speed_rad_s = 0\n", "head.max_speed_rad_s must be in (0, 126] (got 0)"},
           std::pair{"[head]\nmax_speed_rad_s = nan\n", "head.max_speed_rad_s must be a finite number"},
           std::pair{"[head]\nyaw = 1\n", "yaw"},
       }) {
    const std::string message = error_for(text);
    EXPECT_EQ(message.rfind(::testing::TempDir() + "head_config.ini", 0), 0u) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

} // namespace
} // namespace touchline::robot
