// TilePolicy: the policy file format v1 read, its features, Q and greedy action; the same
// worked numbers as tests/behaviour_py/test_tile_policy.py (whose docstring works them out).
#include "touchline/behaviour/skills/tile_policy.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "policy_files.hpp"
#include "touchline/behaviour/registry.hpp"

using namespace touchline::behaviour::skills;
using touchline::behaviour::BehaviourError;
using touchline::behaviour::test::policyText;
using touchline::behaviour::test::TestDataDir;
using touchline::behaviour::test::writePolicy;

namespace {

constexpr size_t FORWARD = 0, LEFT = 1, RIGHT = 2;
constexpr double kPi = 3.14159265358979323846;

TilePolicy testPolicy() { return parsePolicy(policyText(), "test.policy"); }

struct Worked {
  double x, y, theta;
  std::vector<size_t> indices; ///< per tiling, the weight index of action 0
  std::vector<double> q;
  size_t action;
};

} // namespace

TEST(TilePolicy, ReadsTheHeaderAndTheActions) {
  const TilePolicy policy = testPolicy();
  const TilePolicyDef& def = policy.def();
  EXPECT_EQ(def.tilings, 2);
  EXPECT_EQ(def.tilesU, 4);
  EXPECT_EQ(def.tilesB, 8);
  EXPECT_EQ(def.tilesH, 8);
  EXPECT_EQ(def.distanceScale, 100.0);
  EXPECT_EQ(def.maxDistance, 12000.0);
  EXPECT_EQ(def.successDistance, 50.0);
  EXPECT_EQ(def.successHeading, 0.17453);
  ASSERT_EQ(def.actions.size(), 3u);
  EXPECT_EQ(def.actions[0].forward, 300.0);
  EXPECT_EQ(def.actions[1].turn, 1.0);
  EXPECT_EQ(def.actions[2].turn, -1.0);
  EXPECT_EQ(def.weights.size(), 2u * 5 * 8 * 8 * 3);
}

TEST(TilePolicy, WorkedStates) {
  const TilePolicy policy = testPolicy();
  const std::vector<Worked> worked = {
      {1000.0, 500.0, 0.5, {492, 1509}, {1.0, 0.5, 0.0}, FORWARD},
      {-200.0, 800.0, 0.0, {348, 1530}, {0.0, 1.0, 0.0}, LEFT},
      {-300.0, -600.0, 0.0, {228, 1410}, {0.0, 0.0, 1.0}, RIGHT},
      {50000.0, 0.0, 0.0, {876, 1866}, {1.0, 0.5, 0.0}, FORWARD}, // u clamped: the last of Tu + 1 cells
      {0.0, 0.0, 0.0, {108, 1098}, {1.0, 0.5, 0.0}, FORWARD},     // at the target: bearing 0
  };
  for (const Worked& w : worked) {
    EXPECT_EQ(policy.cellIndices(w.x, w.y, w.theta), w.indices) << w.x << ", " << w.y;
    EXPECT_EQ(policy.values(w.x, w.y, w.theta), w.q) << w.x << ", " << w.y;
    EXPECT_EQ(policy.greedyAction(w.x, w.y, w.theta), w.action) << w.x << ", " << w.y;
  }
}

TEST(TilePolicy, HeadingErrorWraps) {
  const TilePolicy policy = testPolicy();
  EXPECT_EQ(policy.cellIndices(1000.0, 500.0, 0.5 + 2 * kPi), policy.cellIndices(1000.0, 500.0, 0.5));
  EXPECT_EQ(policy.cellIndices(1000.0, 500.0, 0.5 - 4 * kPi), policy.cellIndices(1000.0, 500.0, 0.5));
  EXPECT_EQ(wrapAngle(kPi), -kPi);
  EXPECT_EQ(wrapAngle(-kPi), -kPi);
  EXPECT_NEAR(wrapAngle(1.5 * kPi), -0.5 * kPi, 1e-12);
}

TEST(TilePolicy, TiesGoToTheLowestAction) {
  const TilePolicy policy = parsePolicy(policyText([](int, int a) { return a == 0 ? 0.0 : 1.0; }), "ties.policy");
  EXPECT_EQ(policy.values(1000.0, 500.0, 0.5), (std::vector<double>{0.0, 2.0, 2.0}));
  EXPECT_EQ(policy.greedyAction(1000.0, 500.0, 0.5), LEFT);
}

TEST(TilePolicy, ArrivedInsideBothTolerances) {
  const TilePolicy policy = testPolicy();
  EXPECT_TRUE(policy.arrived(30.0, -20.0, 0.1));  // 36 mm, 0.1 rad
  EXPECT_FALSE(policy.arrived(30.0, -20.0, 0.2)); // heading off
  EXPECT_FALSE(policy.arrived(60.0, 0.0, 0.0));   // too far
  EXPECT_TRUE(policy.arrived(0.0, 0.0, 2 * kPi)); // wrapped: on heading
}

namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos) ADD_FAILURE() << "no '" << from << "' in the test policy";
  else text.replace(at, from.size(), to);
  return text;
}

std::string all_replaced(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) text.replace(at, from.size(), to);
  return text;
}

std::string rejection(const std::string& text) {
  try {
    parsePolicy(text, "bad.policy");
  } catch (const BehaviourError& e) {
    return e.what();
  }
  return "accepted";
}

} // namespace

TEST(TilePolicy, CommentsBlankLinesAndCrlfAreRead) {
  const std::string text = all_replaced(
      replaced(policyText(), "features polar-log\n", "\n# a comment\nfeatures polar-log\n"), "\n", "\r\n");
  EXPECT_EQ(parsePolicy(text, "crlf.policy").greedyAction(-200.0, 800.0, 0.0), LEFT);
}

TEST(TilePolicy, BadFilesAreRejectedInOneLine) {
  const std::string good = policyText();
  const std::string lastWeightDropped = good.substr(0, good.rfind(' ')) + "\n";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {replaced(good, "touchline-policy 1", "touchline-polcy 1"),
       "bad.policy: not a policy file (the first line must be 'touchline-policy 1')"},
      {"", "bad.policy: not a policy file (the first line must be 'touchline-policy 1')"},
      {replaced(good, "touchline-policy 1", "touchline-policy 2"),
       "bad.policy: policy format version '2' is not supported (this reader knows 1)"},
      {replaced(good, "tiles 4 8 8\n", ""), "bad.policy: missing 'tiles'"},
      {good.substr(0, good.find("weights")), "bad.policy: missing 'weights'"},
      {replaced(good, "weights 1920", "weights 1919"),
       "bad.policy: 'weights' says 1919, but 2 tilings x 5 x 8 x 8 cells x 3 actions need 1920"},
      {lastWeightDropped, "bad.policy: 1919 weights after 'weights', expected 1920"},
      {replaced(good, "weights 1920\n0 0 0.5 0 0 0.5", "weights 1920\n0 0 0.5 0 0 zero"),
       "bad.policy: weight 5: 'zero' is not a number"},
      {replaced(good, "weights 1920\n0 0 0.5", "weights 1920\nnan 0 0.5"), "bad.policy: weight 0: 'nan' is not a number"},
      {replaced(good, "distance_scale_mm 100", "distance_scale_mm 1OO"),
       "bad.policy: line 4 (distance_scale_mm): '1OO' is not a number"},
      {replaced(good, "distance_scale_mm 100", "distance_scale_mm 0"),
       "bad.policy: 'distance_scale_mm' must be > 0 (got 0)"},
      {replaced(good, "tilings 2", "tilings 2.5"), "bad.policy: line 6 (tilings): '2.5' is not a whole number >= 1"},
      {replaced(good, "features polar-log", "features cartesian"),
       "bad.policy: line 3 (features): unknown feature kind 'cartesian' (known: polar-log)"},
      {replaced(good, "max_distance_mm 12000", "max_distance_mm 12000\nmax_distance_mm 6000"),
       "bad.policy: line 6 (max_distance_mm): 'max_distance_mm' given twice"},
      {replaced(good, "features polar-log", "feature polar-log"), "bad.policy: line 3 (feature): unknown key 'feature'"},
      {replaced(good, "action 0 0 -1\n", ""), "bad.policy: 2 'action' lines, but 'actions' says 3"},
      {replaced(good, "action 0 0 -1", "action 0 -1"), "bad.policy: line 13 (action): expected forward, left, turn"},
      {replaced(good, "tiles 4 8 8", "tiles 1000 1000 1000"),
       "bad.policy: 6006000000 weights is more than " + std::to_string(MAX_POLICY_WEIGHTS)},
  };
  for (const auto& [text, message] : bad) EXPECT_EQ(rejection(text), message);
}

TEST(TilePolicy, AMissingFileIsNamed) {
  const TestDataDir data;
  const std::string path = (data.path() / "nowhere.policy").string();
  try {
    loadPolicy(path);
    FAIL() << "a missing file was read";
  } catch (const BehaviourError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot read the policy (No such file or directory)");
  }
}

TEST(TilePolicy, AFileIsReadOncePerPath) {
  const TestDataDir data;
  const auto path = data.path() / "once.policy";
  writePolicy(path);
  const auto first = cachedPolicy(path.string());
  writePolicy(path, "not a policy any more");
  EXPECT_EQ(cachedPolicy(path.string()), first);
}
