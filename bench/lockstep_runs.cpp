// touchline_bench, part 2: lockstep matches of sim_world and N robot_shim processes.
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <boost/program_options.hpp>
#include <lcm/lcm-cpp.hpp>

#include "touchline/lcm/match_key.hpp"

#include "bench.hpp"

namespace touchline::bench {


struct Child {
  std::string name;  // e.g. "robot_shim --team 0 --player 3"
  std::string log;
  pid_t pid = -1;
};

/// fork + exec argv with stdout and stderr to log; the child dies with us. Throws on exec failure.
Child spawn(const std::string& name, const std::vector<std::string>& argv, const std::string& log) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  int err_pipe[2];  // reports an exec failure (close-on-exec: EOF means exec succeeded)
  if (pipe2(err_pipe, O_CLOEXEC) != 0) throw BenchError(std::string("pipe failed: ") + std::strerror(errno));
  // Every program of a match authenticates with one secret: the first spawn draws it and
  // the children inherit it.
  setenv(touchline::transport::kMatchSecretVariable, touchline::transport::MatchKey::random().hex().c_str(), 0);
  std::cout << std::flush;
  std::cerr << std::flush;
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw BenchError(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    close(err_pipe[0]);
    int err = 0;
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) err = errno;
    const int devnull = open("/dev/null", O_RDONLY);
    if (!err && (devnull < 0 || dup2(devnull, STDIN_FILENO) < 0)) err = errno;
    if (!err && !die_with_parent(parent)) err = ESRCH;
    if (!err) {
      execv(args[0], args.data());
      err = errno;
    }
    if (write(err_pipe[1], &err, sizeof err) < 0) {
    }
    _exit(127);
  }
  close(err_pipe[1]);
  int err = 0;
  ssize_t n;
  while ((n = read(err_pipe[0], &err, sizeof err)) < 0 && errno == EINTR) {
  }
  close(err_pipe[0]);
  if (n > 0) {
    kill_and_reap(pid);
    throw BenchError("cannot start " + argv[0] + ": " + std::strerror(err));
  }
  return Child{name, log, pid};
}


std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The number after "key": in a flat JSON text (the first occurrence), or nullopt.
std::optional<double> json_number(const std::string& text, const std::string& key) {
  const std::string needle = "\"" + key + "\":";
  const size_t at = text.find(needle);
  if (at == std::string::npos) return std::nullopt;
  const char* begin = text.c_str() + at + needle.size();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  return value;
}

long sum_json_numbers(const std::string& text, const std::string& key) {
  const std::string needle = "\"" + key + "\":";
  long sum = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    sum += std::strtol(text.c_str() + at + needle.size(), nullptr, 10);
  return sum;
}

size_t count_occurrences(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

/// One match: sim_world + robots shims, all must exit 0 within timeout_s.
RunResult run_lockstep(const Options& opt, int robots, const std::string& dir, int run_index, double timeout_s) {
  const std::string tag = std::to_string(robots) + "r" + std::to_string(run_index);
  const std::string summary = dir + "/summary_" + tag + ".json";
  const std::string sim_world = opt.bin_dir + "/bin/sim_world";
  const std::string robot_shim = opt.bin_dir + "/bin/robot_shim";
  std::ostringstream duration;
  duration << opt.duration_s;

  std::vector<Child> children;
  const auto kill_all = [&] {
    for (auto& c : children)
      if (c.pid > 0) kill_and_reap(c.pid);
  };
  RunResult result;
  const auto t0 = Clock::now();
  try {
    children.push_back(spawn("sim_world --robots " + std::to_string(robots),
                             {sim_world, "--robots", std::to_string(robots), "--duration", duration.str(),
                              "--quiet", "--summary", summary, "--lcm-url", opt.lcm_url},
                             dir + "/sim_world_" + tag + ".log"));
    for (int i = 0; i < robots; ++i) {
      const std::string team = std::to_string(i / 4), player = std::to_string(i % 4 + 1);
      children.push_back(spawn("robot_shim --team " + team + " --player " + player,
                               {robot_shim, "--team", team, "--player", player, "--behaviour", "walk", "--param",
                                "forward=200", "--param", "turn=0.3", "--lcm-url", opt.lcm_url},
                               dir + "/robot_shim_" + team + "_" + player + "_" + tag + ".log"));
    }
    size_t running = children.size();
    while (running > 0) {
      int status = 0;
      const pid_t pid = waitpid(-1, &status, WNOHANG);
      if (pid > 0) {
        auto it = std::find_if(children.begin(), children.end(), [&](const Child& c) { return c.pid == pid; });
        if (it == children.end()) continue;
        it->pid = -1;
        --running;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
          throw BenchError(it->name + " " + describe_status(status) + " (log: " + it->log + ")");
        continue;
      }
      if (pid < 0 && errno != EINTR) throw BenchError(std::string("waitpid failed: ") + std::strerror(errno));
      if (seconds_since(t0) > timeout_s) {
        std::string late;
        for (const auto& c : children)
          if (c.pid > 0) late += (late.empty() ? "" : ", ") + c.name;
        std::ostringstream msg;
        msg << "lockstep run with " << robots << " robot(s) still running after " << timeout_s
            << " s (see --run-timeout); killed: " << late << " (logs in " << dir << ")";
        throw BenchError(msg.str());
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  } catch (...) {
    kill_all();
    throw;
  }
  result.total_wall_s = seconds_since(t0);

  const std::string text = read_file(summary);
  const auto rtf = json_number(text, "rtf");
  const auto wall = json_number(text, "wall_s");
  if (!rtf || !wall || *rtf <= 0) throw BenchError("sim_world wrote no usable rtf/wall_s to " + summary);
  const size_t active = count_occurrences(text, "\"active\": true");
  if (active != static_cast<size_t>(robots))
    throw BenchError("sim_world: only " + std::to_string(active) + " of " + std::to_string(robots) +
                     " robots were active at the end (a shim timed out; see " + summary + ")");
  if (text.find("\"interrupted\": false") == std::string::npos)
    throw BenchError("sim_world reports the match was interrupted (" + summary + ")");
  result.rtf = *rtf;
  result.sim_wall_s = *wall;
  result.frames_missed = sum_json_numbers(text, "frames_missed");
  return result;
}

LockstepResult measure_lockstep(const Options& opt, int robots, const std::string& dir, double timeout_s) {
  LockstepResult r;
  r.robots = robots;
  std::vector<double> rtfs, sim_walls, total_walls;
  for (int i = 0; i < opt.repeat; ++i) {
    r.runs.push_back(run_lockstep(opt, robots, dir, i, timeout_s));
    rtfs.push_back(r.runs.back().rtf);
    sim_walls.push_back(r.runs.back().sim_wall_s);
    total_walls.push_back(r.runs.back().total_wall_s);
  }
  r.median_rtf = median(rtfs);
  r.median_sim_wall_s = median(sim_walls);
  r.median_total_wall_s = median(total_walls);
  return r;
}


}  // namespace touchline::bench
