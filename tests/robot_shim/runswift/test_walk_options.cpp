// The walk options of the compatibility library: their defaults (checked against their own
// options code in the clone), their .cfg files read as they are, a later file winning, a
// bad file one line naming it, and the values reaching their walk.
#include "touchline/robot/runswift/walk_options.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "touchline/ini.hpp"
#include "touchline/robot/runswift/runswift_walk.hpp"

namespace touchline::robot::runswift {
namespace {

namespace fs = std::filesystem;
namespace po = boost::program_options;

const fs::path kClone = TOUCHLINE_RUNSWIFT_DIR;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A file in a fresh temporary folder of this test.
fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("touchline_walk_options_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

/// Their options code's default for each key, as written there ("0.07f", "false", "3").
std::map<std::string, std::string> their_defaults() {
  const std::string code = read_text(kClone / "robot/utils/options.cpp");
  const std::regex option(R"re(\(\s*"([\w.]+)"\s*,\s*po::value<\w+>\(\)->default_value\(([^)]*)\))re");
  std::map<std::string, std::string> found;
  for (std::sregex_iterator it(code.begin(), code.end(), option), end; it != end; ++it) found[(*it)[1]] = (*it)[2];
  return found;
}

double number(const std::string& text) {
  if (text == "true") return 1;
  if (text == "false") return 0;
  return std::stod(text);
}

double value_of(const po::variable_value& v) {
  if (const auto* f = boost::any_cast<float>(&v.value())) return *f;
  if (const auto* i = boost::any_cast<int>(&v.value())) return *i;
  if (const auto* b = boost::any_cast<bool>(&v.value())) return *b ? 1 : 0;
  ADD_FAILURE() << "unexpected type";
  return NAN;
}

TEST(WalkOptions, DefaultsAreTheirOptionsCodes) {
  const auto theirs = their_defaults();
  const po::variables_map ours = to_variables_map(WalkOptions{});
  ASSERT_EQ(ours.size(), 23u);
  for (const auto& [key, value] : ours) {
    const auto it = theirs.find(key);
    ASSERT_NE(it, theirs.end()) << key << " is not in their options code";
    EXPECT_FLOAT_EQ(static_cast<float>(value_of(value)), static_cast<float>(number(it->second))) << key;
  }
}

TEST(WalkOptions, TheirOwnConfigFilesReadWithoutFault) {
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kClone / "image/home/nao/data")) {
    if (entry.path().extension() != ".cfg") continue;
    EXPECT_NO_THROW(load_walk_options({entry.path().string()})) << entry.path();
    ++files;
  }
  EXPECT_GT(files, 0);
}

TEST(WalkOptions, ALaterFileWinsAndOtherModulesKeysAreSkipped) {
  const auto general = write_file("general.cfg", "[vision]\nseeBalls=1\n[kick]\nlean=12.5\nstableNumFrames=7\n");
  const auto body = write_file("body.cfg", "[kick]\nlean=15\nleanOffsetLVaried=true\n");
  const WalkOptions o = load_walk_options({general.string(), body.string()});
  EXPECT_FLOAT_EQ(o.kick_lean_deg, 15);
  EXPECT_EQ(o.stable_frames, 7);
  EXPECT_TRUE(o.lean_offset_l_varied);
  EXPECT_FLOAT_EQ(o.gyro_kp, WalkOptions{}.gyro_kp);
}

void expect_one_line_naming(const std::string& path, const std::string& fault_part) {
  try {
    load_walk_options({path});
    FAIL() << "no error for " << path;
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind(path, 0), 0u) << what;
    EXPECT_NE(what.find(fault_part), std::string::npos) << what;
  }
}

TEST(WalkOptions, AFileThatDoesNotParseIsOneLineNamingItAndTheFault) {
  expect_one_line_naming(write_file("number.cfg", "[kick]\nlean=twenty\n").string(), "kick.lean");
  expect_one_line_naming(write_file("inf.cfg", "[motion]\nKpGyro=inf\n").string(), "motion.KpGyro");
  expect_one_line_naming(write_file("bool.cfg", "[kick]\nleanOffsetRVaried=maybe\n").string(), "leanOffsetRVaried");
  expect_one_line_naming(write_file("frames.cfg", "[kick]\nstableNumFrames=-1\n").string(), "kick.stableNumFrames");
  expect_one_line_naming(write_file("syntax.cfg", "[kick\nlean=1\n").string(), "invalid line");
  expect_one_line_naming("/nonexistent/runswift.cfg", "cannot open");
}

TEST(WalkOptions, TheWalkRefusesABadFileAtStart) {
  RunswiftWalkDef def;
  def.option_files = {write_file("bad.cfg", "[motion]\nKpAngle=x\n").string()};
  EXPECT_THROW(RunswiftWalk walk(def), ConfigError);
}

/// The stance ankle's pitch after walking a while with a steady pitch rate on the gyro.
float stance_ankle_with_gyro(const RunswiftWalkDef& def) {
  RunswiftWalk walk(def);
  nao::NaoSensorFrame s;
  s.left_foot = s.right_foot = {1.3f, 1.3f, 1.3f, 1.3f};
  nao::WalkCommand c;
  c.kind = nao::WalkCommand::Kind::walk;
  c.forward_mm_s = 100;
  nao::NaoJointFrame out;
  for (int i = 0; i < 150; ++i) {
    s.gyro_y_rad_s = i > 100 ? 0.5f : 0.f;
    out = walk.step(c, s);
    s.joint_angles_rad = out.joint_angles_rad;
  }
  return out.joint_angles_rad[walk.left_foot_swinging() ? nao::RAnklePitch : nao::LAnklePitch];
}

TEST(WalkOptions, AFileValueReachesTheirWalk) {
  // motion.KpGyro scales their ankle's answer to the gyro: 0 leaves the ankle alone.
  RunswiftWalkDef no_gyro;
  no_gyro.option_files = {write_file("gyro.cfg", "[motion]\nKpGyro=0\nKdGyro=0\n").string()};
  const float with_default = stance_ankle_with_gyro({});
  const float without = stance_ankle_with_gyro(no_gyro);
  EXPECT_GT(std::fabs(with_default - without), 0.01f) << with_default << " vs " << without;
}

} // namespace
} // namespace touchline::robot::runswift
