// touchline_behaviour_bench: what one behaviour tick costs, Python (embedded, with its
// Blackboard access) against the C++ port, on the GoToBall runs of the port corpus; and,
// on the same Blackboards, the rUNSWift profile (their Blackboard built, tick, their
// request converted) with our own test behaviour in their style and, given
// --runswift-dir, their release's WalkToPoint + HeadFindBall.
// Also replays every run of the corpus (a fresh behaviour per run, frames in order, as the
// port-regression test does) and reports the Team skill's mean tick, Python and C++ (the
// figure a match's behaviour_cpu_us_mean shows); --requests PATH writes every Python
// request of that replay, floats in hex, so that a change to the tick's cost can be shown
// to leave what the behaviour decides bit for bit as it was (diff two files); --cold MIB
// writes that much memory between two ticks of the replay, as the other processes of a match
// sharing the cores do to the caches (a match's tick costs several times a warm one).
// Prints median and p90 per tick in microseconds; --json PATH writes them.
#include <pybind11/embed.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <numeric>
#include <sstream>
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

/// Issue #14: py:Team's mean tick at most this, us (what 4 v 4 in-process at x100 on one core needs).
constexpr double kTeamTickGoalUs = 50;

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
  double median_us = 0, p90_us = 0, mean_us = 0;
};

Figures figures_of(std::vector<double> us) {
  if (us.empty()) return {};
  std::sort(us.begin(), us.end());
  return {us[us.size() / 2], us[us.size() * 9 / 10],
          std::accumulate(us.begin(), us.end(), 0.0) / static_cast<double>(us.size())};
}

/// One robot's run in the corpus: consecutive snapshots of one channel with one behaviour.
struct RobotRun {
  std::string channel;
  std::string behaviour; ///< "py skill=Team ..." as the shim recorded it
  std::map<std::string, std::string> params;
  std::vector<int64_t> frame_numbers;
  std::vector<api::Blackboard> frames;
};

/// "py skill=GoToBall x=1" -> {skill: GoToBall, x: 1}
std::map<std::string, std::string> params_of(const std::string& behaviour) {
  std::map<std::string, std::string> params;
  std::istringstream words(behaviour);
  std::string word;
  words >> word; // the behaviour name ("py")
  while (words >> word)
    if (const auto eq = word.find('='); eq != std::string::npos) params[word.substr(0, eq)] = word.substr(eq + 1);
  return params;
}

std::vector<RobotRun> corpus_runs(const std::string& corpus) {
  ::lcm::LogFile log(corpus, "r");
  if (!log.good()) throw std::runtime_error("cannot read " + corpus);
  std::vector<RobotRun> runs;
  std::map<std::string, size_t> open; // channel -> its current run
  while (const ::lcm::LogEvent* event = log.readNextEvent()) {
    blackboard_snapshot_t snapshot;
    if (snapshot.decode(event->data, 0, event->datalen) < 0) continue;
    auto it = open.find(event->channel);
    const bool continues = it != open.end() && runs[it->second].behaviour == snapshot.skill &&
                           runs[it->second].frame_numbers.back() < snapshot.frame;
    if (!continues) {
      runs.push_back({event->channel, snapshot.skill, params_of(snapshot.skill), {}, {}});
      open[event->channel] = runs.size() - 1;
    }
    runs[open[event->channel]].frame_numbers.push_back(snapshot.frame);
    runs[open[event->channel]].frames.push_back(transport::from_snapshot(snapshot));
  }
  return runs;
}

/// A request as text, floats in hex: equal lines, equal bits.
std::string describe_request(const api::ActionCommand::All& r) {
  char line[512];
  std::snprintf(line, sizeof line, "body %d %a %a %a %a %a %a %d head %a %a %d %a %a led %d msg", static_cast<int>(r.body.actionType),
                r.body.forward, r.body.left, r.body.turn, r.body.power, r.body.bend, r.body.speed,
                static_cast<int>(r.body.foot), r.head.yaw, r.head.pitch, r.head.isRelative ? 1 : 0, r.head.yawSpeed,
                r.head.pitchSpeed, static_cast<int>(r.leds.chest));
  std::string text = line;
  for (uint8_t byte : r.teamMessage) {
    char hex[4];
    std::snprintf(hex, sizeof hex, " %02x", byte);
    text += hex;
  }
  return text;
}

struct Replay {
  Figures team_python, team_cpp, all_python;
  size_t team_frames = 0, all_frames = 0;
};

/// This thread's CPU time, us: what a match charges a behaviour tick (BehaviourAdapter), and
/// unlike wall time not inflated when other processes take the CPU away mid-tick.
double thread_cpu_us() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) * 1e-3;
}

/// Every corpus run, `rounds` times, each with fresh behaviours, timed in thread CPU time;
/// the first round's Python requests to `requests` when it is open.
Replay replay_corpus(const std::vector<RobotRun>& runs, const python::PythonBehaviourDef& runtime, int rounds,
                     std::ostream* requests, size_t evict_bytes) {
  std::vector<uint8_t> evict(evict_bytes);
  std::vector<double> team_py, team_cpp, all_py;
  Replay replay;
  for (int round = 0; round < rounds; ++round) {
    for (const RobotRun& run : runs) {
      robot::RobotDef python_robot;
      python_robot.behaviour = {"py", run.params, TOUCHLINE_BEHAVIOUR_PY};
      auto py = apps::make_behaviour(python_robot, runtime);
      robot::RobotDef cpp_robot;
      cpp_robot.behaviour = {run.params.count("skill") ? run.params.at("skill") : "GoToBall", run.params, ""};
      cpp_robot.behaviour.params.erase("skill");
      auto cpp = apps::make_behaviour(cpp_robot);
      const bool team = run.params.count("skill") && run.params.at("skill") == "Team";
      for (size_t i = 0; i < run.frames.size(); ++i) {
        // --cold: what the other processes of a match do to the caches between two ticks.
        for (size_t at = 0; at < evict.size(); at += 64) evict[at] = static_cast<uint8_t>(evict[at] + i);
        const double start = thread_cpu_us();
        const api::ActionCommand::All request = py->tick(run.frames[i]);
        const double us = thread_cpu_us() - start;
        all_py.push_back(us);
        if (team) team_py.push_back(us);
        if (requests && round == 0)
          *requests << run.channel << " " << run.behaviour << " " << run.frame_numbers[i] << ": "
                    << describe_request(request) << "\n";
        if (team) {
          const double cpp_start = thread_cpu_us();
          const api::ActionCommand::All cpp_request = cpp->tick(run.frames[i]);
          team_cpp.push_back(thread_cpu_us() - cpp_start);
          if (cpp_request.body.speed < 0) std::cerr << ""; // keeps the call observable
        }
      }
    }
  }
  replay.team_frames = team_py.size() / static_cast<size_t>(rounds);
  replay.all_frames = all_py.size() / static_cast<size_t>(rounds);
  replay.team_python = figures_of(std::move(team_py));
  replay.team_cpp = figures_of(std::move(team_cpp));
  replay.all_python = figures_of(std::move(all_py));
  return replay;
}

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
  return figures_of(std::move(us));
}

} // namespace

int main(int argc, char** argv) {
  std::string json_path;
  std::string runswift_dir;
  std::string requests_path;
  int rounds = 5;
  size_t evict_bytes = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--json" && i + 1 < argc) {
      json_path = argv[++i];
    } else if (arg == "--runswift-dir" && i + 1 < argc) {
      runswift_dir = argv[++i];
    } else if (arg == "--requests" && i + 1 < argc) {
      requests_path = argv[++i];
    } else if (arg == "--cold" && i + 1 < argc) {
      evict_bytes = static_cast<size_t>(std::max(0, std::atoi(argv[++i]))) << 20;
    } else if (arg == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else {
      std::cerr << "touchline_behaviour_bench: unknown argument '" << arg << "' (options: --json PATH, --rounds N, --requests PATH, --cold MIB, --runswift-dir DIR)\n";
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
    // The whole corpus, Team's runs among them, fresh behaviours per run.
    std::ofstream requests_file;
    if (!requests_path.empty()) {
      requests_file.open(requests_path);
      if (!requests_file) throw std::runtime_error("cannot write " + requests_path);
    }
    const auto runs = corpus_runs(TOUCHLINE_CORPUS);
    const Replay replay = replay_corpus(runs, runtime, rounds, requests_path.empty() ? nullptr : &requests_file, evict_bytes);
    if (requests_file.is_open() && !requests_file.flush()) throw std::runtime_error("cannot write " + requests_path);
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
              << "behaviour tick, Team, " << replay.team_frames << " corpus frames x " << rounds
              << " rounds (every run replayed in order by a fresh behaviour; thread CPU time per tick"
              << (evict_bytes ? ", " + std::to_string(evict_bytes >> 20) + " MiB written between ticks" : std::string())
              << ")\n"
              << "  python (embedded, behaviour.tick)  mean " << replay.team_python.mean_us << " us, median "
              << replay.team_python.median_us << " us, p90 " << replay.team_python.p90_us << " us; mean x"
              << replay.team_python.mean_us / kTeamTickGoalUs << " the goal (<= " << static_cast<int>(kTeamTickGoalUs)
              << " us, issue #14; a match adds swapping the robots' modules and colder caches)\n"
              << "  c++ port                           mean " << replay.team_cpp.mean_us << " us, median "
              << replay.team_cpp.median_us << " us, p90 " << replay.team_cpp.p90_us << " us\n"
              << "  python, every skill (" << replay.all_frames << " frames) mean " << replay.all_python.mean_us
              << " us, median " << replay.all_python.median_us << " us\n"
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
          << ",\n  \"python_team_tick_mean_us\": " << replay.team_python.mean_us
          << ",\n  \"python_team_tick_median_us\": " << replay.team_python.median_us
          << ",\n  \"python_team_tick_goal_us\": " << kTeamTickGoalUs
          << ",\n  \"cpp_team_tick_mean_us\": " << replay.team_cpp.mean_us
          << ",\n  \"python_corpus_tick_mean_us\": " << replay.all_python.mean_us
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
