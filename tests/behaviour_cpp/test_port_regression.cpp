// Port regression: the C++ behaviour must do what the Python original does. Every robot's
// run in the corpus (tests/data/port_corpus.lcmlog, Blackboard snapshots recorded from real
// matches of the Python behaviour; re-record with tools/record_corpus.py) is fed frame by
// frame to the embedded Python behaviour and to its C++ port, both fresh, and each frame's
// ActionCommand must agree: discrete fields exactly, floats within kAbs + kRel * |value|.
//
// The learned-walker runs (walker=learned, LearnedGoToPose) are replayed with the trained
// policy (config/policies/go_to_pose.policy) when it is there, else with the test policy of
// skills/policy_files.hpp: any policy tests that both ports pick the same actions.
#include <pybind11/embed.h>

#include <filesystem>
#include <iostream>

#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "touchline/apps/behaviour_factory.hpp"
#include "touchline/blackboard_snapshot_t.hpp"
#include "touchline/lcm/snapshot.hpp"
#include "touchline/python/python_behaviour.hpp"
#include "touchline/behaviour/skills/tile_policy.hpp"
#include "touchline/robot_api/data.hpp"

#include "skills/policy_files.hpp"

using namespace touchline;
namespace AC = api::ActionCommand;

namespace {

constexpr float kAbs = 1e-3f; ///< mm/s, rad, rad/s: far below anything a robot could act on
constexpr float kRel = 1e-4f; ///< float32 C++ against float64 Python

/// One robot's run: consecutive snapshots of one channel with one behaviour.
struct RobotRun {
  std::string channel;
  std::string behaviour; ///< "py skill=GoToBall ..." as the shim recorded it
  std::vector<blackboard_snapshot_t> frames;
};

std::vector<RobotRun> load_corpus() {
  ::lcm::LogFile log(TOUCHLINE_CORPUS, "r");
  if (!log.good()) throw std::runtime_error(std::string("cannot read ") + TOUCHLINE_CORPUS);
  std::vector<RobotRun> runs;
  std::map<std::string, size_t> open; // channel -> index of its current run
  while (const ::lcm::LogEvent* event = log.readNextEvent()) {
    blackboard_snapshot_t snapshot;
    if (snapshot.decode(event->data, 0, event->datalen) < 0)
      throw std::runtime_error("corpus event " + std::to_string(event->eventnum) + " is not a blackboard_snapshot_t");
    auto it = open.find(event->channel);
    const bool continues = it != open.end() && runs[it->second].behaviour == snapshot.skill &&
                           runs[it->second].frames.back().frame < snapshot.frame;
    if (!continues) {
      runs.push_back({event->channel, snapshot.skill, {}});
      open[event->channel] = runs.size() - 1;
    }
    runs[open[event->channel]].frames.push_back(snapshot);
  }
  return runs;
}

/// Why the corpus could not be read ("" if it could): reported by a test, never thrown
/// while gtest instantiates the tests (that would abort the whole binary).
std::string& corpus_error() {
  static std::string error;
  return error;
}

const std::vector<RobotRun>& corpus() {
  static const std::vector<RobotRun> runs = [] {
    try {
      return load_corpus();
    } catch (const std::exception& e) {
      corpus_error() = std::string(e.what()) + " (re-record it with tools/record_corpus.py)";
      return std::vector<RobotRun>{};
    }
  }();
  return runs;
}

/// "py skill=GoToBall x=1" -> {skill: GoToBall, x: 1}
std::map<std::string, std::string> params_of(const std::string& behaviour) {
  std::map<std::string, std::string> params;
  std::istringstream words(behaviour);
  std::string word;
  words >> word; // the behaviour name ("py")
  while (words >> word) {
    const auto eq = word.find('=');
    if (eq != std::string::npos) params[word.substr(0, eq)] = word.substr(eq + 1);
  }
  return params;
}

/// Collects the fields where two requests differ, as "name: python X, c++ Y".
class Differences {
 public:
  void exact(const char* name, long python, long cpp) {
    if (python != cpp) add(name, std::to_string(python), std::to_string(cpp));
  }
  void close(const char* name, float python, float cpp) {
    if (!(std::fabs(python - cpp) <= kAbs + kRel * std::fabs(python))) add(name, std::to_string(python), std::to_string(cpp));
  }
  bool empty() const { return text_.empty(); }
  const std::string& text() const { return text_; }

 private:
  void add(const char* name, const std::string& python, const std::string& cpp) {
    text_ += std::string(text_.empty() ? "" : "; ") + name + ": python " + python + ", c++ " + cpp;
  }
  std::string text_;
};

std::string compare(const AC::All& py, const AC::All& cpp) {
  Differences d;
  d.exact("body.actionType", static_cast<long>(py.body.actionType), static_cast<long>(cpp.body.actionType));
  d.exact("body.foot", static_cast<long>(py.body.foot), static_cast<long>(cpp.body.foot));
  d.close("body.forward", py.body.forward, cpp.body.forward);
  d.close("body.left", py.body.left, cpp.body.left);
  d.close("body.turn", py.body.turn, cpp.body.turn);
  d.close("body.power", py.body.power, cpp.body.power);
  d.close("body.bend", py.body.bend, cpp.body.bend);
  d.close("body.speed", py.body.speed, cpp.body.speed);
  d.exact("head.isRelative", py.head.isRelative, cpp.head.isRelative);
  d.close("head.yaw", py.head.yaw, cpp.head.yaw);
  d.close("head.pitch", py.head.pitch, cpp.head.pitch);
  d.close("head.yawSpeed", py.head.yawSpeed, cpp.head.yawSpeed);
  d.close("head.pitchSpeed", py.head.pitchSpeed, cpp.head.pitchSpeed);
  d.exact("leds.chest", py.leds.chest, cpp.leds.chest);
  return d.text();
}

class PortRegression : public ::testing::TestWithParam<size_t> {
 protected:
  static void SetUpTestSuite() {
    if (!Py_IsInitialized()) interpreter_ = std::make_unique<pybind11::scoped_interpreter>(false, 0, nullptr, false);
    const std::string trained = api::data_path(behaviour::skills::DEFAULT_POLICY);
    if (std::filesystem::is_regular_file(trained)) {
      std::cout << "learned runs replayed with " << trained << "\n";
    } else {
      testData_ = std::make_unique<behaviour::test::TestDataDir>();
      std::cout << "learned runs replayed with the test policy (no " << trained << " yet)\n";
    }
  }
  static void TearDownTestSuite() { testData_.reset(); }
  static std::unique_ptr<pybind11::scoped_interpreter> interpreter_;
  static std::unique_ptr<behaviour::test::TestDataDir> testData_;
};
std::unique_ptr<pybind11::scoped_interpreter> PortRegression::interpreter_;
std::unique_ptr<behaviour::test::TestDataDir> PortRegression::testData_;

TEST_P(PortRegression, CppPortAgreesWithPythonOnEveryFrame) {
  const RobotRun& run = corpus()[GetParam()];
  auto params = params_of(run.behaviour);
  // The recorded robot as robot_shim made it (--behaviour py --param skill=...), and its C++ port.
  robot::RobotDef recorded;
  recorded.id = {run.frames.front().team, run.frames.front().player};
  recorded.behaviour = {"py", params, TOUCHLINE_BEHAVIOUR_PY};
  python::PythonBehaviourDef runtime;
  runtime.reload_check_interval_us = int64_t{1} << 60; // the files do not change during the test
  auto python_owner = apps::make_behaviour(recorded, runtime);
  auto& python = dynamic_cast<python::PythonBehaviour&>(*python_owner);
  robot::RobotDef port = recorded;
  port.behaviour.name = params.count("skill") ? params["skill"] : "GoToBall";
  port.behaviour.params.erase("skill");
  auto cpp = apps::make_behaviour(port);

  int failures = 0;
  for (const blackboard_snapshot_t& frame : run.frames) {
    const api::Blackboard blackboard = transport::from_snapshot(frame);
    const AC::All from_python = python.tick(blackboard);
    ASSERT_TRUE(python.healthy()) << run.channel << " frame " << frame.frame << ": the Python behaviour failed";
    const std::string diff = compare(from_python, cpp->tick(blackboard));
    if (!diff.empty() && ++failures <= 5)
      ADD_FAILURE() << run.channel << " (" << run.behaviour << ") frame " << frame.frame << ": " << diff;
  }
  EXPECT_EQ(failures, 0) << failures << " of " << run.frames.size() << " frames differ";
}

std::string run_name(const ::testing::TestParamInfo<size_t>& info) {
  const RobotRun& run = corpus()[info.param];
  std::string skill = params_of(run.behaviour)["skill"];
  std::string name = std::to_string(info.param) + "_" + skill + "_" + run.channel.substr(run.channel.size() - 3);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

std::vector<size_t> run_indices() {
  std::vector<size_t> indices(corpus().size());
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  return indices;
}

INSTANTIATE_TEST_SUITE_P(Corpus, PortRegression, ::testing::ValuesIn(run_indices()), run_name);

TEST(PortCorpus, HasThousandsOfFramesCoveringEverySkill) {
  ASSERT_EQ(corpus_error(), "");
  size_t frames = 0;
  std::set<std::string> skills;
  for (const RobotRun& run : corpus()) {
    frames += run.frames.size();
    auto params = params_of(run.behaviour);
    skills.insert(params["skill"] + (params["walker"] == "learned" ? " walker=learned" : ""));
  }
  EXPECT_GE(frames, 3000u);
  const std::set<std::string> every = {
      "GoToBall", "GoToPose",   "LineUpAndKick", "TrackBall",       "HeadScan",
      "Team",     "Striker",    "Goalie",        "Midfielder",      "Defender",
      "LearnedGoToPose", "GoToBall walker=learned", "Striker walker=learned"};
  for (const std::string& skill : every) EXPECT_TRUE(skills.count(skill)) << "no frames of " << skill;
}

TEST(PortCorpus, IsInTheFormThatARecordingReproducesByteForByte) {
  // tools/record_corpus.py stamps each snapshot with its simulated time, orders a scenario's
  // snapshots by (time, robot) and drops the bus's tag, so that the same build records the
  // same file and a re-recorded corpus's diff is the behaviour's, not the recording's.
  ::lcm::LogFile log(TOUCHLINE_CORPUS, "r");
  ASSERT_TRUE(log.good()) << TOUCHLINE_CORPUS;
  int64_t last_utime = -1;
  std::string last_channel;
  int events = 0;
  while (const ::lcm::LogEvent* event = log.readNextEvent()) {
    ++events;
    blackboard_snapshot_t snapshot;
    ASSERT_EQ(snapshot.decode(event->data, 0, event->datalen), event->datalen) << "event " << event->eventnum;
    EXPECT_EQ(event->timestamp, snapshot.utime) << "event " << event->eventnum;
    const bool next_scenario = snapshot.utime < last_utime;
    EXPECT_TRUE(next_scenario || snapshot.utime > last_utime || event->channel > last_channel)
        << "event " << event->eventnum << " (" << event->channel << " at " << snapshot.utime << ") out of order";
    last_utime = snapshot.utime;
    last_channel = event->channel;
  }
  EXPECT_GE(events, 3000);
}

} // namespace
