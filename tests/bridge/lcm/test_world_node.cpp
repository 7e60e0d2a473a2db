// Both LCM nodes, the world's and the robots', on LCM's in-process transport (memq://): one
// bus shared by the world and two RobotNodes in this process, no network. The world's loop
// dispatches every message, so the robots play through their handlers alone: join, a sense
// per frame answered with an act, team messages, FINISHED at the end.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <spdlog/logger.h>
#include <spdlog/sinks/ostream_sink.h>

#include "touchline/join_t.hpp"
#include "touchline/lcm/bus.hpp"
#include "touchline/lcm/robot_node.hpp"
#include "touchline/lcm/world_messages.hpp"
#include "touchline/lcm/world_node.hpp"
#include "touchline/robot/robot.hpp"
#include "touchline/robot/robot_def.hpp"
#include "touchline/sim/config.hpp"
#include "touchline/sim/match.hpp"

using namespace touchline;

namespace {

/// Walks forward and tells its teammates the frame it is in.
class WalkAndTalk : public api::Behaviour {
 public:
  api::ActionCommand::All tick(const api::Blackboard&) override {
    api::ActionCommand::All all;
    all.body = api::ActionCommand::walk(200, 0, 0.2f);
    all.teamMessage = {static_cast<uint8_t>(++ticks_)};
    return all;
  }

 private:
  int ticks_ = 0;
};

struct Played {
  transport::RunSummary summary;
  std::vector<bool> over;
  std::vector<match_event_t> heard; ///< every TL_EVENT a listener on the bus decoded
  std::string log;                  ///< the world's lines to the user
  int64_t silent_missed = 0;        ///< frames the silent robot (if any) missed
};

/// A robot_shim that joined as team 1 player 2 from process `pid` and never answers.
constexpr int kSilentPid = 4242;

/// Plays with the referee off unless `rules` says otherwise (its "rules.*" settings); with
/// `world` the world node's settings, and a silent robot beside the two that play when
/// `silent`.
Played play(uint64_t seed, double duration_s, std::vector<std::string> rules = {"rules.referee=false"},
            transport::WorldNodeDef world = {}, bool silent = false) {
  rules.push_back(silent ? "match.team_size=2" : "match.team_size=1");
  rules.push_back("match.duration_s=" + std::to_string(duration_s));
  sim::WorldConfig config = sim::load_world_config("", rules);
  sim::Match match(config, seed);
  transport::Bus bus("memq://", transport::MatchKey::random());
  std::ostringstream lines;
  spdlog::logger log("world_node_test", std::make_shared<spdlog::sinks::ostream_sink_st>(lines));

  world.robots = silent ? 3 : 2;
  world.progress = false;
  transport::RobotNodeDef robot_def;
  robot_def.snapshot_every = 0;
  // memq:// drops a message that nobody subscribes to when it is sent: this keeps the joins
  // queued until the world, which subscribes when it starts, takes them.
  bus.subscribe(transport::kJoinChannel, [](const transport::BusMessage&) {});
  std::vector<match_event_t> heard;
  bus.subscribe(transport::kEventChannel, [&heard](const transport::BusMessage& m) {
    match_event_t event;
    transport::decode(m.payload, static_cast<int>(m.payload_size), m.channel, event);
    heard.push_back(event);
  });
  std::vector<std::unique_ptr<robot::Robot>> robots;
  std::vector<std::unique_ptr<transport::RobotNode>> nodes;
  for (int team = 0; team < 2; ++team) {
    robot::RobotDef def;
    def.id = {team, 1};
    robots.push_back(std::make_unique<robot::Robot>(def, std::make_unique<WalkAndTalk>()));
    nodes.push_back(std::make_unique<transport::RobotNode>(*robots.back(), robot_def, bus, log));
    nodes.back()->request_join(); // answered inside the world's loop below
  }
  if (silent) {
    join_t join;
    join.team = 1;
    join.player = 2;
    join.instance = 99;
    join.pid = kSilentPid;
    bus.publish(transport::kJoinChannel, join);
  }
  Played played{transport::run_world(match, world, bus, log), {}, {}, {}, 0};
  played.heard = std::move(heard);
  played.log = lines.str();
  if (silent) played.silent_missed = match.roster().find({1, 2})->frames_missed;
  for (const auto& node : nodes) played.over.push_back(node->match_over());
  EXPECT_EQ(bus.counters().unauthenticated, 0) << lines.str();
  EXPECT_EQ(bus.counters().handler_failures, 0) << lines.str();
  return played;
}

} // namespace

TEST(WorldNodeOverMemq, TheRobotNodesAnswerEveryFrameAndHearTheEnd) {
  const Played played = play(7, 2.0);
  EXPECT_EQ(played.summary.frames, 60);
  EXPECT_EQ(played.summary.malformed, 0);
  EXPECT_EQ(played.summary.stale, 0);
  EXPECT_EQ(played.summary.resent_senses, 0); // nothing is lost in process
  EXPECT_EQ(played.over, (std::vector<bool>{true, true}));
}

TEST(WorldNodeOverMemq, TheSameSeedGivesTheSameMatch) {
  const Played first = play(7, 1.0);
  EXPECT_EQ(first.summary.frames, 30);
  EXPECT_EQ(play(7, 1.0).summary.truth_hash, first.summary.truth_hash);
}

TEST(WorldNodeOverMemq, TheSummaryKeepsEveryEventItPublished) {
  // The launcher reports goals, penalties and falls from the summary, not from the bus,
  // which may drop some of them under load.
  const Played played = play(7, 2.0, {"rules.initial_s=0", "rules.ready_s=0.5", "rules.set_s=0.5"});
  ASSERT_GE(played.heard.size(), 2u); // READY, SET, PLAYING
  ASSERT_EQ(played.summary.events.size(), played.heard.size());
  for (size_t i = 0; i < played.heard.size(); ++i) {
    const match_event_t kept = transport::to_msg(played.summary.events[i]);
    EXPECT_EQ(kept.utime, played.heard[i].utime) << i;
    EXPECT_EQ(kept.kind, played.heard[i].kind) << i;
    EXPECT_EQ(kept.text, played.heard[i].text) << i;
  }
}

TEST(WorldNodeOverMemq, ARobotWhoseShimRunsIsWaitedForUpToTheLiveTimeout) {
  // A busy machine, or a breakpoint: timing the robot out would change the match.
  transport::WorldNodeDef world;
  world.robot_timeout_ms = 20;
  world.live_robot_timeout_ms = 200;
  std::vector<int> asked;
  world.shim_runs = [&asked](int pid) {
    asked.push_back(pid);
    return pid == kSilentPid;
  };
  const Played played = play(7, 0.5, {"rules.referee=false"}, world, /*silent=*/true);
  ASSERT_FALSE(asked.empty());
  EXPECT_EQ(asked.front(), kSilentPid);
  EXPECT_EQ(played.summary.slow_answers, 1); // then it is inactive, and no longer waited for
  EXPECT_NE(played.log.find("team 1 player 2 has not answered frame 0 in 20 ms, but its robot_shim still runs"),
            std::string::npos) << played.log;
  EXPECT_NE(played.log.find("team 1 player 2 no answer within 200 ms at frame 0 though its robot_shim runs"),
            std::string::npos) << played.log;
  EXPECT_EQ(played.silent_missed, played.summary.frames);
}

TEST(WorldNodeOverMemq, ARobotWhoseShimIsGoneIsTimedOutAtTheRobotTimeout) {
  transport::WorldNodeDef world;
  world.robot_timeout_ms = 20;
  world.live_robot_timeout_ms = 60000; // never reached: the test would take a minute
  world.shim_runs = [](int) { return false; };
  const Played played = play(7, 0.5, {"rules.referee=false"}, world, /*silent=*/true);
  EXPECT_EQ(played.summary.slow_answers, 0);
  EXPECT_NE(played.log.find("team 1 player 2 no answer within 20 ms at frame 0; it stands still"), std::string::npos)
      << played.log;
  EXPECT_EQ(played.log.find("still runs"), std::string::npos) << played.log;
  EXPECT_EQ(played.silent_missed, played.summary.frames);
}
