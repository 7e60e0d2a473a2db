// touchline_behaviour_bench: what one behaviour tick costs, Python (embedded, with its
// Blackboard access) against the C++ port, on the GoToBall runs of the port corpus; and,
// on the same Blackboards, the rUNSWift profile (their Blackboard built, tick, their
// request converted) with our own test behaviour in their style and, given
// --runswift-dir, their release's WalkToPoint + HeadFindBall.
// Prints median and p90 per tick in microseconds; --json PATH writes them.
#include <pybind11/embed.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "touchline/apps/behaviour_factory.hpp"
#include "touchline/blackboard_snapshot_t.hpp"
#include "touchline/lcm/snapshot.hpp"
#include "touchline/python/runswift/profile.hpp"

using namespace touchline;
using Clock = std::chrono::steady_clock;

namespace {

std::vector<api::Blackboard> go_to_ball_frames(const std::string& corpus) {
  ::lcm::LogFile log(corpus, "r");
  if (!log.good()) throw std::runtime_error("cannot read " + corpus);
  std::vector<api::Blackboard> frames;
  while (const ::lcm::LogEvent* event = log.readNextEvent()) {
    blackboard_snapshot_t snapshot;
    if (snapshot.decode(event->data, 0, event->datalen) < 0) continue;
    if (snapshot.skill == "py skill=GoToBall") frames.push_back(transport::from_snapshot(snapshot));
  }
  if (frames.empty()) throw std::runtime_error(corpus + " has no GoToBall frames");
  return frames;
}

struct Figures {
  double median_us = 0, p90_us = 0;
};

/// Ticks `behaviour` over every frame `rounds` times; per-tick wall time.
Figures time_ticks(api::Behaviour& behaviour, const std::vector<api::Blackboard>& frames, int rounds) {
  std::vector<double> us;
  us.reserve(frames.size() * static_cast<size_t>(rounds));
  for (int r = 0; r < rounds; ++r) {
    for (const api::Blackboard& blackboard : frames) {
      const auto start = Clock::now();
      const api::ActionCommand::All request = behaviour.tick(blackboard);
      const auto end = Clock::now();
      if (request.body.speed < 0) std::cerr << ""; // keeps the call observable
      us.push_back(std::chrono::duration<double, std::micro>(end - start).count());
    }
  }
  std::sort(us.begin(), us.end());
  return {us[us.size() / 2], us[us.size() * 9 / 10]};
}

} // namespace

int main(int argc, char** argv) {
  std::string json_path;
  std::string runswift_dir;
  int rounds = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--json" && i + 1 < argc) {
      json_path = argv[++i];
    } else if (arg == "--runswift-dir" && i + 1 < argc) {
      runswift_dir = argv[++i];
    } else if (arg == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else {
      std::cerr << "touchline_behaviour_bench: unknown argument '" << arg << "' (options: --json PATH, --rounds N, --runswift-dir DIR)\n";
      return 2;
    }
  }
  try {
    const auto frames = go_to_ball_frames(TOUCHLINE_CORPUS);
    pybind11::scoped_interpreter interpreter(false, 0, nullptr, false);
    // The two robots as robot_shim makes them: --behaviour py --param skill=GoToBall, --behaviour GoToBall.
    robot::RobotDef python_robot;
    python_robot.behaviour = {"py", {{"skill", "GoToBall"}}, TOUCHLINE_BEHAVIOUR_PY};
    python::PythonBehaviourDef runtime;
    runtime.reload_check_interval_us = int64_t{1} << 60; // measure the tick, not the file watch
    auto py = apps::make_behaviour(python_robot, runtime);
    robot::RobotDef cpp_robot;
    cpp_robot.behaviour.name = "GoToBall";
    auto cpp = apps::make_behaviour(cpp_robot);
    time_ticks(*py, frames, 1); // warm up
    const Figures python_figures = time_ticks(*py, frames, rounds);
    const Figures cpp_figures = time_ticks(*cpp, frames, rounds);
    // The rUNSWift profile, as robot_shim --behaviour runswift makes it.
    auto runswift = [&](const std::string& dir, const std::string& skill, const std::string& headskill) {
      python::PythonBehaviourDef def = runtime;
      def.directory = dir;
      python::runswift::RunswiftDef rs;
      rs.blackboard.skill = skill;
      rs.blackboard.headskill = headskill;
      def.profile = python::runswift::make_profile(rs);
      python::PythonBehaviour behaviour(def);
      time_ticks(behaviour, frames, 1); // warm up: their imports
      return time_ticks(behaviour, frames, rounds);
    };
    const Figures ours_figures = runswift(TOUCHLINE_RUNSWIFT_TEST_BEHAVIOUR, "Striker", "HeadScan");
    Figures theirs_figures;
    if (!runswift_dir.empty()) theirs_figures = runswift(runswift_dir, "WalkToPoint", "HeadFindBall");

    std::cout << std::fixed << std::setprecision(2) << "behaviour tick, GoToBall, " << frames.size()
              << " corpus frames x " << rounds << " rounds (wall time per tick)\n"
              << "  python (embedded, behaviour.tick)  median " << python_figures.median_us << " us, p90 "
              << python_figures.p90_us << " us\n"
              << "  c++ port                           median " << cpp_figures.median_us << " us, p90 "
              << cpp_figures.p90_us << " us\n"
              << "  runswift profile, our test Striker median " << ours_figures.median_us << " us, p90 "
              << ours_figures.p90_us << " us\n";
    if (!runswift_dir.empty())
      std::cout << "  runswift profile, their WalkToPoint + HeadFindBall median " << theirs_figures.median_us
                << " us, p90 " << theirs_figures.p90_us << " us\n";
    if (!json_path.empty()) {
      std::ofstream out(json_path);
      out << std::setprecision(6) << "{\n  \"python_tick_median_us\": " << python_figures.median_us
          << ",\n  \"python_tick_p90_us\": " << python_figures.p90_us << ",\n  \"cpp_tick_median_us\": "
          << cpp_figures.median_us << ",\n  \"cpp_tick_p90_us\": " << cpp_figures.p90_us
          << ",\n  \"runswift_test_tick_median_us\": " << ours_figures.median_us
          << ",\n  \"runswift_test_tick_p90_us\": " << ours_figures.p90_us;
      if (!runswift_dir.empty())
        out << ",\n  \"runswift_release_tick_median_us\": " << theirs_figures.median_us
            << ",\n  \"runswift_release_tick_p90_us\": " << theirs_figures.p90_us;
      out
          << ",\n  \"frames\": " << frames.size() << ",\n  \"rounds\": " << rounds << "\n}\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "touchline_behaviour_bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
