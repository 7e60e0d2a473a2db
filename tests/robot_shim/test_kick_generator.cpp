// KickGenerator and its routing through the MotionAdapter: phases and their lengths in
// ticks, the swing's profile, latching, power and the dribble; load_kick_def.
#include "touchline/robot/kick_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "touchline/ini.hpp"
#include "touchline/robot/motion_adapter.hpp"

namespace touchline::robot {
namespace {

using api::ActionCommand::ActionType;
using api::ActionCommand::Body;
using api::ActionCommand::Foot;

constexpr float kTickS = 0.01f;

Body kick_request(ActionType type = ActionType::KICK, float power = 1.f, float bend = 0.f,
                  Foot foot = Foot::LEFT) {
  Body body;
  body.actionType = type;
  body.power = power;
  body.bend = bend;
  body.foot = foot;
  return body;
}

/// What one MotionAdapter tick did.
struct Tick {
  int phase = 0;
  FootMotion left, right;
  ActionType active = ActionType::STAND;
};

/// Ticks `motion` with `request` in force until the kick it runs has completed (or
/// `max_ticks`), recording every tick.
std::vector<Tick> run(MotionAdapter& motion, api::Blackboard& board, int max_ticks = 2000) {
  std::vector<Tick> ticks;
  for (int i = 0; i < max_ticks; ++i) {
    const TickMotion out = motion.tick(board);
    ticks.push_back({board.motion.kickPhase, out.left, out.right, board.motion.active.actionType});
    if (i > 0 && !motion.kick().running()) break;
  }
  return ticks;
}

/// Moves `feet` by one tick's motions as sim::World does: each foot's displacement is in
/// the body frame at the tick's start, whose heading is the feet's circular mean.
void apply_as_the_world_does(FeetPose& feet, const Tick& t) {
  const float heading = std::atan2(std::sin(feet.left.theta_rad) + std::sin(feet.right.theta_rad),
                                   std::cos(feet.left.theta_rad) + std::cos(feet.right.theta_rad));
  const float c = std::cos(heading), s = std::sin(heading);
  for (auto [foot, m] : {std::pair{&feet.left, t.left}, std::pair{&feet.right, t.right}}) {
    foot->x_mm += c * m.dx_mm - s * m.dy_mm;
    foot->y_mm += s * m.dx_mm + c * m.dy_mm;
    foot->theta_rad += m.dtheta_rad;
  }
}

/// Largest per-tick travel of a foot, mm.
float peak_step(const std::vector<Tick>& ticks, Foot foot) {
  float peak = 0;
  for (const Tick& t : ticks) {
    const FootMotion& m = foot == Foot::LEFT ? t.left : t.right;
    peak = std::max(peak, std::hypot(m.dx_mm, m.dy_mm));
  }
  return peak;
}

TEST(KickGenerator, FromStandingRunsPrepareSwingRecoverForTheirConfiguredTicks) {
  const KickDef def;
  MotionAdapter motion(WalkDef{}, HeadDef{}, def);
  api::Blackboard board;
  board.behaviour.request.body = kick_request();
  const std::vector<Tick> ticks = run(motion, board);

  const int prepare = duration_ticks(def.kick.prepare_s);
  const int swing = plan_swing(def.kick, 1.f, 0.f).total_ticks();
  const int recover = duration_ticks(def.kick.recover_s);
  EXPECT_EQ(prepare, 40);
  EXPECT_EQ(recover, 40);
  ASSERT_EQ(static_cast<int>(ticks.size()), prepare + swing + recover);
  for (size_t i = 0; i < ticks.size(); ++i) {
    const int expected = static_cast<int>(i) < prepare ? 1 : static_cast<int>(i) < prepare + swing ? 2 : 3;
    EXPECT_EQ(ticks[i].phase, expected) << "tick " << i;
    EXPECT_EQ(ticks[i].active, ActionType::KICK) << "tick " << i;
  }
  EXPECT_FALSE(motion.kick().running());
}

TEST(KickGenerator, OnlyTheKickingFootMovesAndOnlyInTheSwing) {
  for (Foot foot : {Foot::LEFT, Foot::RIGHT}) {
    MotionAdapter motion(WalkDef{});
    api::Blackboard board;
    board.behaviour.request.body = kick_request(ActionType::KICK, 1.f, 0.3f, foot);
    for (const Tick& t : run(motion, board)) {
      const FootMotion& other = foot == Foot::LEFT ? t.right : t.left;
      EXPECT_EQ(other.dx_mm, 0.f);
      EXPECT_EQ(other.dy_mm, 0.f);
      EXPECT_EQ(other.dtheta_rad, 0.f);
      if (t.phase != 2) {
        const FootMotion& kicking = foot == Foot::LEFT ? t.left : t.right;
        EXPECT_EQ(kicking.dx_mm, 0.f);
        EXPECT_EQ(kicking.dtheta_rad, 0.f);
      }
    }
  }
}

TEST(KickGenerator, SwingReturnsTheFootExactlyToWhereItStarted) {
  // Through the generator: the feet after the swing are the walk's, bit for bit ...
  WalkCycle walk;
  const FeetPose start = walk.feet();
  KickGenerator kick;
  kick.start(kick_request(ActionType::KICK, 0.7f, -0.4f, Foot::RIGHT));
  FeetPose feet = start;
  float farthest = 0;
  while (kick.running()) {
    feet = kick.tick(walk);
    farthest = std::max(farthest, std::hypot(feet.right.x_mm - start.right.x_mm, feet.right.y_mm - start.right.y_mm));
  }
  EXPECT_GT(farthest, 100.f);
  EXPECT_EQ(feet.right.x_mm, start.right.x_mm);
  EXPECT_EQ(feet.right.y_mm, start.right.y_mm);
  EXPECT_EQ(feet.right.theta_rad, start.right.theta_rad);
  EXPECT_EQ(feet.left.x_mm, start.left.x_mm);

  // ... and the per-tick motions the world is sent, applied as the world applies them,
  // bring both feet back to where they were.
  MotionAdapter motion(WalkDef{});
  api::Blackboard board;
  board.behaviour.request.body = kick_request(ActionType::KICK, 1.f, 0.2f);
  FeetPose world = motion.walk().feet();
  const FeetPose placed = world;
  for (const Tick& t : run(motion, board)) apply_as_the_world_does(world, t);
  EXPECT_NEAR(world.left.x_mm, placed.left.x_mm, 1e-3f);
  EXPECT_NEAR(world.left.y_mm, placed.left.y_mm, 1e-3f);
  EXPECT_NEAR(world.left.theta_rad, placed.left.theta_rad, 1e-6f);
  EXPECT_EQ(world.right.x_mm, placed.right.x_mm);
  EXPECT_EQ(world.right.y_mm, placed.right.y_mm);
}

TEST(KickGenerator, SwingDrawsBackStrikesAlongTheBendAndReturns) {
  const SwingDef def;
  const SwingPlan plan = plan_swing(def, 1.f, 0.3f);
  EXPECT_FLOAT_EQ(plan.bend_rad, 0.3f);
  float least = 0, most = 0;
  for (int i = 0; i <= plan.total_ticks(); ++i) {
    const SwingOffset o = swing_offset(plan, i);
    least = std::min(least, o.along_mm);
    most = std::max(most, o.along_mm);
    // Turned fully to bend for the whole strike.
    if (i >= plan.windup_ticks && i <= plan.windup_ticks + plan.strike_ticks) {
      EXPECT_FLOAT_EQ(o.turn_rad, 0.3f) << i;
    }
  }
  EXPECT_FLOAT_EQ(least, -def.backswing_mm);
  EXPECT_FLOAT_EQ(most, def.swing_length_mm);
  EXPECT_EQ(swing_offset(plan, plan.total_ticks()).along_mm, 0.f);
  EXPECT_EQ(swing_offset(plan, plan.total_ticks()).turn_rad, 0.f);

  // In the odometry frame the foot's farthest point lies along the bend.
  WalkCycle walk;
  const Pose2D start = walk.feet().left;
  KickGenerator kick;
  kick.start(kick_request(ActionType::KICK, 1.f, 0.3f));
  Pose2D farthest = start;
  while (kick.running()) {
    const Pose2D foot = kick.tick(walk).left;
    if (foot.x_mm > farthest.x_mm) farthest = foot;
  }
  EXPECT_NEAR(std::atan2(farthest.y_mm - start.y_mm, farthest.x_mm - start.x_mm), 0.3f, 1e-4f);
  EXPECT_NEAR(std::hypot(farthest.y_mm - start.y_mm, farthest.x_mm - start.x_mm), def.swing_length_mm, 1e-3f);
  EXPECT_NEAR(farthest.theta_rad, 0.3f, 1e-6f);
}

TEST(KickGenerator, PowerScalesThePeakFootSpeed) {
  std::vector<float> peaks;
  for (float power : {1.f, 0.5f}) {
    MotionAdapter motion(WalkDef{});
    api::Blackboard board;
    board.behaviour.request.body = kick_request(ActionType::KICK, power);
    peaks.push_back(peak_step(run(motion, board), Foot::LEFT) / kTickS);
  }
  const SwingDef def;
  EXPECT_LE(peaks[0], def.peak_speed_mm_s);
  EXPECT_GT(peaks[0], 0.95f * def.peak_speed_mm_s); // whole ticks cost at most a few percent
  EXPECT_NEAR(peaks[1] / peaks[0], 0.5f, 0.03f);
  // Below min_power the strike does not crawl; NaN counts as no power.
  EXPECT_EQ(plan_swing(def, 0.f, 0.f).strike_ticks, plan_swing(def, def.min_power, 0.f).strike_ticks);
  EXPECT_EQ(plan_swing(def, NAN, 0.f).strike_ticks, plan_swing(def, def.min_power, 0.f).strike_ticks);
  EXPECT_EQ(plan_swing(def, 7.f, 0.f).strike_ticks, plan_swing(def, 1.f, 0.f).strike_ticks);
}

TEST(KickGenerator, BendIsClampedToItsLimit) {
  const SwingDef def;
  EXPECT_FLOAT_EQ(plan_swing(def, 1.f, 2.f).bend_rad, def.max_bend_rad);
  EXPECT_FLOAT_EQ(plan_swing(def, 1.f, -2.f).bend_rad, -def.max_bend_rad);
  EXPECT_EQ(plan_swing(def, 1.f, NAN).bend_rad, 0.f);
}

TEST(KickGenerator, DribbleIsShorterAndWeakerThanAKick) {
  std::vector<size_t> lengths;
  std::vector<float> peaks;
  for (ActionType type : {ActionType::KICK, ActionType::DRIBBLE}) {
    MotionAdapter motion(WalkDef{});
    api::Blackboard board;
    board.behaviour.request.body = kick_request(type);
    const std::vector<Tick> ticks = run(motion, board);
    lengths.push_back(ticks.size());
    peaks.push_back(peak_step(ticks, Foot::LEFT));
    EXPECT_EQ(ticks.front().active, type);
  }
  EXPECT_LT(lengths[1], lengths[0]);
  EXPECT_LT(peaks[1], 0.7f * peaks[0]);
}

TEST(KickGenerator, PrepareFirstBringsTheWalkToAStandWithFeetSquare) {
  MotionAdapter motion(WalkDef{});
  api::Blackboard board;
  board.behaviour.request.body = api::ActionCommand::walk(300, 0, 0.5f);
  for (int i = 0; i < 150; ++i) motion.tick(board);
  ASSERT_FALSE(motion.walk().standing());

  board.behaviour.request.body = kick_request();
  int prepare = 0;
  bool feet_moved_in_prepare = false;
  while (true) {
    const TickMotion out = motion.tick(board);
    if (board.motion.kickPhase != 1) break;
    ++prepare;
    feet_moved_in_prepare |= out.left.dx_mm != 0 || out.right.dx_mm != 0;
  }
  EXPECT_TRUE(feet_moved_in_prepare); // the walk finished its steps
  EXPECT_GT(prepare, duration_ticks(KickDef{}.kick.prepare_s));
  EXPECT_EQ(board.motion.kickPhase, 2);
  EXPECT_TRUE(motion.walk().standing());
  const FeetPose& feet = motion.walk().feet();
  EXPECT_NEAR(feet.left.theta_rad, feet.right.theta_rad, 1e-5f);
  EXPECT_NEAR(std::hypot(feet.left.x_mm - feet.right.x_mm, feet.left.y_mm - feet.right.y_mm), 100.f, 1e-2f);
}

TEST(KickGenerator, AStartedKickIgnoresRequestChangesUntilItCompletes) {
  const int kick_ticks = [] {
    MotionAdapter motion(WalkDef{});
    api::Blackboard board;
    board.behaviour.request.body = kick_request();
    return static_cast<int>(run(motion, board).size());
  }();

  MotionAdapter motion(WalkDef{});
  api::Blackboard board;
  board.behaviour.request.body = kick_request(ActionType::KICK, 1.f);
  motion.tick(board);
  // Walk, then a weaker dribble with the other foot: the kick carries on as latched.
  board.behaviour.request.body = api::ActionCommand::walk(300, 0, 0);
  for (int i = 1; i < 20; ++i) motion.tick(board);
  board.behaviour.request.body = kick_request(ActionType::DRIBBLE, 0.2f, 0.5f, Foot::RIGHT);
  int ticks = 20;
  for (; motion.kick().running(); ++ticks) {
    const TickMotion out = motion.tick(board);
    EXPECT_EQ(board.motion.active.actionType, ActionType::KICK);
    EXPECT_EQ(board.motion.active.foot, Foot::LEFT);
    EXPECT_EQ(out.right.dx_mm, 0.f);
  }
  EXPECT_EQ(ticks, kick_ticks);
  EXPECT_EQ(motion.kick().plan().strike_speed_mm_s, KickDef{}.kick.peak_speed_mm_s);

  // The request still asks for a dribble: once the kick is done, the dribble starts.
  motion.tick(board);
  EXPECT_EQ(board.motion.kickPhase, 1);
  EXPECT_EQ(board.motion.active.actionType, ActionType::DRIBBLE);
  EXPECT_EQ(board.motion.active.foot, Foot::RIGHT);
}

TEST(KickGenerator, WalksOnOnceTheKickHasCompleted) {
  MotionAdapter motion(WalkDef{});
  api::Blackboard board;
  board.behaviour.request.body = kick_request(ActionType::DRIBBLE);
  run(motion, board);
  board.behaviour.request.body = api::ActionCommand::walk(200, 0, 0);
  for (int i = 0; i < 100; ++i) motion.tick(board);
  EXPECT_EQ(board.motion.kickPhase, 0);
  EXPECT_EQ(board.motion.active.actionType, ActionType::WALK);
  EXPECT_FALSE(board.motion.standing);
  EXPECT_GT(board.motion.odometry.x, 50.f);
}

TEST(KickGenerator, NoKickWithoutAKickRequest) {
  KickGenerator kick;
  kick.start(api::ActionCommand::walk(100, 0, 0));
  EXPECT_FALSE(kick.running());
  WalkCycle walk;
  kick.tick(walk);
  EXPECT_EQ(kick.last_phase(), KickPhase::kNone);
}

// --- load_kick_def ---------------------------------------------------------------------

const std::string kShippedKick = std::string(TOUCHLINE_SOURCE_DIR) + "/config/kick.ini";

std::string error_for(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "kick_config_" + name + ".ini";
  std::ofstream(path) << text;
  try {
    load_kick_def(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

void expect_same(const SwingDef& a, const SwingDef& b) {
  EXPECT_EQ(a.prepare_s, b.prepare_s);
  EXPECT_EQ(a.backswing_mm, b.backswing_mm);
  EXPECT_EQ(a.swing_length_mm, b.swing_length_mm);
  EXPECT_EQ(a.peak_speed_mm_s, b.peak_speed_mm_s);
  EXPECT_EQ(a.min_power, b.min_power);
  EXPECT_EQ(a.reposition_speed_mm_s, b.reposition_speed_mm_s);
  EXPECT_EQ(a.aim_speed_rad_s, b.aim_speed_rad_s);
  EXPECT_EQ(a.max_bend_rad, b.max_bend_rad);
  EXPECT_EQ(a.recover_s, b.recover_s);
}

TEST(KickConfig, ShippedFileAgreesWithTheStructDefaults) {
  const KickDef shipped = load_kick_def(kShippedKick);
  expect_same(shipped.kick, KickDef{}.kick);
  expect_same(shipped.dribble, KickDef{}.dribble);
  expect_same(load_kick_def("").dribble, default_dribble_def());
}

TEST(KickConfig, ShippedFileWritesOutEveryKeyOfBothSectionsUnderAComment) {
  const std::set<std::string> keys = {"prepare_s",       "backswing_mm", "swing_length_mm",
                                      "peak_speed_mm_s", "min_power",    "reposition_speed_mm_s",
                                      "aim_speed_rad_s", "max_bend_rad", "recover_s"};
  std::set<std::string> expected;
  for (const char* section : {"kick", "dribble"})
    for (const std::string& key : keys) expected.insert(std::string(section) + "." + key);
  std::ifstream in(kShippedKick);
  ASSERT_TRUE(in) << kShippedKick;
  std::set<std::string> found;
  std::string line, previous, section;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') section = line.substr(1, line.find(']') - 1);
    const auto eq = line.find('=');
    if (!line.empty() && line[0] != '#' && eq != std::string::npos) {
      std::string key = line.substr(0, eq);
      key.erase(key.find_last_not_of(' ') + 1);
      EXPECT_EQ(previous.rfind('#', 0), 0u) << key << " has no comment line above it";
      found.insert(section + "." + key);
    }
    previous = line;
  }
  EXPECT_EQ(found, expected);
}

TEST(KickConfig, KeysInTheFileOverrideTheDefaults) {
  const std::string path = ::testing::TempDir() + "kick_config_override.ini";
  std::ofstream(path) << "[kick]\npeak_speed_mm_s = 1200\n[dribble]\nrecover_s = 0.3\n";
  const KickDef def = load_kick_def(path);
  EXPECT_EQ(def.kick.peak_speed_mm_s, 1200.f);
  EXPECT_FLOAT_EQ(def.dribble.recover_s, 0.3f);
  EXPECT_EQ(def.kick.recover_s, KickDef{}.kick.recover_s);
}

TEST(KickConfig, BadValuesAreOneLineErrorsNamingTheKey) {
  const std::string speed = error_for("speed", "[kick]\npeak_speed_mm_s = 5000\n");
  EXPECT_NE(speed.find("kick_config_speed.ini: kick.peak_speed_mm_s must be in (0, 3000] (got 5000)"),
            std::string::npos)
      << speed;
  EXPECT_EQ(speed.find('\n'), std::string::npos);
  EXPECT_NE(error_for("prepare", "[dribble]\nprepare_s = -1\n").find("dribble.prepare_s"), std::string::npos);
  EXPECT_NE(error_for("length", "[kick]\nswing_length_mm = 0\n").find("kick.swing_length_mm"), std::string::npos);
  EXPECT_NE(error_for("power", "[kick]\nmin_power = 0\n").find("kick.min_power"), std::string::npos);
  EXPECT_NE(error_for("bend", "[dribble]\nmax_bend_rad = 2\n").find("dribble.max_bend_rad"), std::string::npos);
  EXPECT_NE(error_for("nan", "[kick]\naim_speed_rad_s = nan\n").find("kick.aim_speed_rad_s"), std::string::npos);
  EXPECT_NE(error_for("word", "[kick]\nrecover_s = soon\n").find("kick.recover_s"), std::string::npos);
  const std::string unknown = error_for("unknown", "[kick]\nspin_rad_s = 3\n");
  EXPECT_NE(unknown.find("kick.spin_rad_s"), std::string::npos) << unknown;
  EXPECT_EQ(error_for("fine", "[kick]\nbackswing_mm = 0\n"), "");
}

TEST(KickConfig, InfiniteNanAndHugeValuesAreErrorsNamingTheKey) {
  EXPECT_EQ(error_for("inf", "[kick]\nprepare_s = inf\n"),
            ::testing::TempDir() + "kick_config_inf.ini: kick.prepare_s must be a finite number (got 'inf')");
  EXPECT_EQ(error_for("huge", "[dribble]\nswing_length_mm = 1e30\n"),
            ::testing::TempDir() + "kick_config_huge.ini: dribble.swing_length_mm must be in (0, 1000] (got 1e+30)");
  EXPECT_NE(error_for("recover", "[kick]\nrecover_s = 1e9\n").find("kick.recover_s must be in [0, 10]"),
            std::string::npos);
  EXPECT_NE(error_for("aim", "[kick]\naim_speed_rad_s = -inf\n").find("kick.aim_speed_rad_s"), std::string::npos);
}

TEST(KickConfig, ADirectoryIsNoKickFile) {
  const std::string dir = std::string(TOUCHLINE_SOURCE_DIR) + "/config";
  try {
    load_kick_def(dir);
    FAIL() << "a directory read as an empty kick file";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), (dir + ": cannot open config file (it is a directory)").c_str());
  }
}

TEST(KickConfig, MissingFileIsAnErrorNamingThePath) {
  const std::string path = ::testing::TempDir() + "no_such_kick.ini";
  try {
    load_kick_def(path);
    FAIL() << "no error for a missing file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace touchline::robot
