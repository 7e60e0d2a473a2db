#include "touchline/learning/observation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "touchline/learning/pose_message.hpp"

using namespace touchline;

namespace {

/// Player 2 of team 1 in a team of 3, PLAYING, with a ball, a heard teammate and two robots seen.
api::Blackboard blackboard() {
  api::Blackboard bb;
  bb.utime = 10'000'000;
  bb.localisation.robotPos = {-1000, 500, 0.25f};
  bb.localisation.ballPos = {200, -300, 0};
  bb.localisation.ballPosRR = {1000, 0.5f};
  bb.localisation.ballLostCount = 15;
  bb.localisation.ballVel = {120, -40, 0};
  bb.motion.active = api::ActionCommand::walk(250, -50, 0.4f);
  bb.motion.headYaw = -0.3f;
  bb.motion.standing = false;
  bb.motion.kickPhase = 2;
  bb.gameController.state = api::GameState::PLAYING;
  bb.gameController.team = 1;
  bb.gameController.playerNumber = 2;
  bb.gameController.score = {{3, 1}};
  bb.gameController.secsRemaining = 77;
  bb.gameController.firstHalf = false;
  bb.gameController.kickOffTeam = 1;
  bb.gameController.setPlay = api::SetPlay::KICK_IN;
  bb.gameController.setPlayTeam = 0;
  bb.receiver.messages.push_back({3, 9'500'000, learning::encode_pose_message({700, -800, 1.5f})});
  bb.vision.robots.push_back({{2000, 0}, 4, false});
  bb.vision.robots.push_back({{500, 1.5707964f}, 1, true});
  return bb;
}

std::vector<float> observe(const api::Blackboard& bb, int team_size) {
  std::vector<float> out(static_cast<size_t>(learning::observation_size(team_size)), -99.f);
  learning::observe(bb, team_size, out.data());
  return out;
}

float at(const std::vector<float>& obs, int team_size, const std::string& name) {
  const auto names = learning::observation_names(team_size);
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  return obs.at(static_cast<size_t>(it - names.begin()));
}

} // namespace

TEST(Observation, EveryElementHasAUniqueName) {
  for (int team_size = 1; team_size <= 7; ++team_size) {
    auto names = learning::observation_names(team_size);
    EXPECT_EQ(static_cast<int>(names.size()), learning::observation_size(team_size));
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  }
}

TEST(Observation, WritesEveryElementAndNoMore) {
  std::vector<float> out(static_cast<size_t>(learning::observation_size(3)) + 1, -99.f);
  learning::observe(blackboard(), 3, out.data());
  EXPECT_EQ(std::count(out.begin(), out.end(), -99.f), 1);
  EXPECT_EQ(out.back(), -99.f);
}

TEST(Observation, ReadsTheRobotsOwnBeliefsInItsUnits) {
  const auto o = observe(blackboard(), 3);
  EXPECT_EQ(at(o, 3, "self_x_mm"), -1000.f);
  EXPECT_EQ(at(o, 3, "self_theta_rad"), 0.25f);
  EXPECT_EQ(at(o, 3, "ball_y_mm"), -300.f);
  EXPECT_NEAR(at(o, 3, "ball_rel_x_mm"), 1000 * std::cos(0.5f), 1e-3);
  EXPECT_NEAR(at(o, 3, "ball_rel_y_mm"), 1000 * std::sin(0.5f), 1e-3);
  EXPECT_NEAR(at(o, 3, "ball_lost_s"), 0.5f, 1e-6);
  EXPECT_EQ(at(o, 3, "ball_vx_mm_s"), 120.f);
  EXPECT_EQ(at(o, 3, "walk_left_mm_s"), -50.f);
  EXPECT_EQ(at(o, 3, "head_yaw_rad"), -0.3f);
  EXPECT_EQ(at(o, 3, "standing"), 0.f);
  EXPECT_EQ(at(o, 3, "kicking"), 1.f);
}

TEST(Observation, TheGameIsSeenFromTheRobotsTeam) {
  const auto o = observe(blackboard(), 3);
  EXPECT_EQ(at(o, 3, "state_playing"), 1.f);
  EXPECT_EQ(at(o, 3, "state_ready") + at(o, 3, "state_set") + at(o, 3, "state_initial"), 0.f);
  EXPECT_EQ(at(o, 3, "our_score"), 1.f); // team 1's
  EXPECT_EQ(at(o, 3, "their_score"), 3.f);
  EXPECT_EQ(at(o, 3, "secs_remaining"), 77.f);
  EXPECT_EQ(at(o, 3, "our_kickoff"), 1.f);
  EXPECT_EQ(at(o, 3, "set_play_ours"), 0.f);
  EXPECT_EQ(at(o, 3, "set_play_theirs"), 1.f);
}

TEST(Observation, TeammatesAreWhatTheirLastPoseMessagesSaid) {
  const auto o = observe(blackboard(), 3);
  // Player 2's slots: mate1 is player 1 (never heard), mate2 player 3.
  EXPECT_EQ(at(o, 3, "mate1_heard"), 0.f);
  EXPECT_EQ(at(o, 3, "mate1_age_s"), learning::kMaxAge_s);
  EXPECT_EQ(at(o, 3, "mate2_heard"), 1.f);
  EXPECT_EQ(at(o, 3, "mate2_x_mm"), 700.f);
  EXPECT_EQ(at(o, 3, "mate2_y_mm"), -800.f);
  EXPECT_NEAR(at(o, 3, "mate2_theta_rad"), 1.5f, 1e-3);
  EXPECT_NEAR(at(o, 3, "mate2_age_s"), 0.5f, 1e-6);
}

TEST(Observation, SeenRobotsComeNearestFirstThenEmptySlots) {
  const auto o = observe(blackboard(), 3);
  EXPECT_NEAR(at(o, 3, "seen1_rel_x_mm"), 0.f, 1e-3);
  EXPECT_NEAR(at(o, 3, "seen1_rel_y_mm"), 500.f, 1e-3);
  EXPECT_EQ(at(o, 3, "seen1_teammate"), 1.f);
  EXPECT_NEAR(at(o, 3, "seen2_rel_x_mm"), 2000.f, 1e-3);
  EXPECT_EQ(at(o, 3, "seen2_teammate"), 0.f);
  EXPECT_EQ(at(o, 3, "seen2_present"), 1.f);
  EXPECT_EQ(at(o, 3, "seen3_present"), 0.f);
  EXPECT_EQ(at(o, 3, "seen4_rel_x_mm"), 0.f);
}
