// The field constants their code reads come from the world's config file.
#include "touchline/python/runswift/field.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "touchline/ini.hpp"

using namespace touchline;
using namespace touchline::python::runswift;

TEST(SplField, TheModernFieldComesFromItsConfig) {
  const SplFieldDef f = load_spl_field(std::string(TOUCHLINE_SOURCE_DIR) + "/config/spl2020.ini");
  EXPECT_FLOAT_EQ(f.length_mm, 9000);
  EXPECT_FLOAT_EQ(f.width_mm, 6000);
  EXPECT_FLOAT_EQ(f.goal_width_mm, 1500);
  EXPECT_FLOAT_EQ(f.goal_box_length_mm, 600);
  EXPECT_FLOAT_EQ(f.goal_box_width_mm, 2200);
  EXPECT_FLOAT_EQ(f.penalty_area_length_mm, 1650);
  EXPECT_FLOAT_EQ(f.penalty_area_width_mm, 4000);
  EXPECT_FLOAT_EQ(f.penalty_mark_distance_mm, 1300);
  EXPECT_FLOAT_EQ(f.centre_circle_diameter_mm, 1500);
  EXPECT_FLOAT_EQ(f.ball_diameter_mm, 100);
}

TEST(SplField, NoFileIsTheWorldsDefaultField) {
  const SplFieldDef f = load_spl_field("");
  EXPECT_FLOAT_EQ(f.length_mm, 6000);
  EXPECT_FLOAT_EQ(f.width_mm, 4000);
  EXPECT_FLOAT_EQ(f.penalty_area_length_mm, 0);
}

TEST(SplField, AnImpossibleValueIsOneLineNamingFileAndKey) {
  const std::string path = testing::TempDir() + "runswift_field.ini";
  std::ofstream(path) << "[field]\nlength_mm = 9000\ngoal_box_length_mm = 6000\n";
  try {
    load_spl_field(path);
    ADD_FAILURE() << "a goal box longer than half the field";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": field.goal_box_length_mm must be in [0, 4500] (got 6000)");
  }
  std::remove(path.c_str());
}
