// What the two round-trip floors share (lcm_floor.cpp over LCM, bus_floor.cpp over the match
// bus): forking the responders, waiting until they all answer, timing the rounds, then
// stopping the responders.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <thread>

#include "bench.hpp"

namespace touchline::bench {

std::vector<pid_t> fork_responders(int count, const std::function<void(int index)>& responder_main) {
  std::cout << std::flush;
  std::cerr << std::flush;
  std::vector<pid_t> children;
  for (int i = 0; i < count; ++i) {
    const pid_t pid = fork();
    if (pid < 0) {
      const std::string reason = std::strerror(errno);
      for (pid_t child : children) kill_and_reap(child);
      throw BenchError("fork failed: " + reason);
    }
    if (pid == 0) responder_main(i);
    children.push_back(pid);
  }
  return children;
}

void await_responders(const std::function<bool(int timeout_ms)>& round, std::vector<pid_t>& children,
                      const std::string& what, const std::function<std::string()>& silent, const std::string& hint) {
  const auto join_start = Clock::now();
  while (!round(50)) {
    for (pid_t pid : children) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        children.erase(std::find(children.begin(), children.end(), pid));
        throw BenchError(what + " (pid " + std::to_string(pid) + ") " + describe_status(status) + " before answering");
      }
    }
    if (seconds_since(join_start) > 10) throw BenchError(silent() + " never answered a ping within 10 s" + hint);
  }
}

void time_rounds(const Options& opt, const std::function<bool(int timeout_ms)>& round, const std::string& what,
                 FloorResult& result, const std::function<std::string()>& detail) {
  std::vector<double> rtt_us;
  rtt_us.reserve(static_cast<size_t>(opt.rounds));
  for (int i = 0; i < opt.warmup + opt.rounds; ++i) {
    const auto t0 = Clock::now();
    const bool ok = round(1000);
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
    if (!ok) {
      if (++result.lost_rounds > std::max(10, (opt.warmup + opt.rounds) / 100))
        throw BenchError(what + ": " + std::to_string(result.lost_rounds) + " rounds lost" + (detail ? detail() : ""));
      continue;
    }
    if (i >= opt.warmup) rtt_us.push_back(us);
  }
  if (rtt_us.empty()) throw BenchError(what + ": no round completed");
  result.median_us = median(rtt_us);
  result.p90_us = percentile(rtt_us, 0.9);
  result.min_us = *std::min_element(rtt_us.begin(), rtt_us.end());
  result.max_us = *std::max_element(rtt_us.begin(), rtt_us.end());
}

void stop_responders(std::vector<pid_t>& children, const std::function<void()>& send_stop, const std::string& what) {
  const auto stop_start = Clock::now();
  while (!children.empty() && seconds_since(stop_start) < 2) {
    send_stop();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    for (auto it = children.begin(); it != children.end();) {
      int status = 0;
      if (waitpid(*it, &status, WNOHANG) == *it) {
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
          throw BenchError(what + " (pid " + std::to_string(*it) + ") " + describe_status(status));
        it = children.erase(it);
      } else {
        ++it;
      }
    }
  }
  if (!children.empty())
    throw BenchError(std::to_string(children.size()) + " " + what + "(s) ignored the stop message for 2 s");
}

} // namespace touchline::bench
