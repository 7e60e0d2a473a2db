#pragma once
// Shared pieces of touchline_bench: options, results, process helpers, and the two
// measurements (lcm_floor.cpp, lockstep_runs.cpp).
#include <sys/types.h>

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace touchline::bench {


constexpr int kFailure = 1;
constexpr int kUsageError = 2;
constexpr const char* kPingChannel = "TLBENCH_PING";
constexpr const char* kStopChannel = "TLBENCH_STOP";
constexpr const char* kPongPrefix = "TLBENCH_PONG_";
constexpr double kFramePeriodUs = 1e6 / 30.0;  // one 30 Hz camera frame

using Clock = std::chrono::steady_clock;

/// A failure to report as one line (exit status 1).
struct BenchError : std::runtime_error {
  using std::runtime_error::runtime_error;
};


struct Options {
  std::string bin_dir;
  std::string lcm_url = "udpm://239.255.76.67:7667?ttl=0";
  std::string json_path;
  double duration_s = 60;
  int repeat = 3;
  int rounds = 3000;
  int warmup = 200;
  double run_timeout_s = -1;  // < 0: derived from the duration
  bool keep_logs = false;
};

struct FloorResult {
  int responders = 0;
  double median_us = 0;
  double p90_us = 0;
  double min_us = 0;
  double max_us = 0;
  int lost_rounds = 0;  // rounds where some pong never came (not timed)
};

struct RunResult {
  double rtf = 0;
  double sim_wall_s = 0;   // sim_world's own wall time of the match loop
  double total_wall_s = 0; // spawn to last exit (process start-up, join, shutdown included)
  long frames_missed = 0;
};

struct LockstepResult {
  int robots = 0;
  std::vector<RunResult> runs;
  double median_rtf = 0;
  double median_sim_wall_s = 0;
  double median_total_wall_s = 0;
};

double seconds_since(Clock::time_point t0);
/// Nearest-rank percentile (q in [0, 1]) of a copy of xs; xs must not be empty.
double percentile(std::vector<double> xs, double q);
double median(const std::vector<double>& xs);
std::string describe_status(int status);
/// Makes this (forked) child die with its parent; returns false if the parent is already gone.
bool die_with_parent(pid_t parent);
void kill_and_reap(pid_t pid);

/// Forks `count` responders, child `i` running responder_main(i) (which never returns), with
/// stdio flushed first so nothing buffered is written twice; on a failed fork kills those
/// started and throws BenchError (round_trips.cpp).
std::vector<pid_t> fork_responders(int count, const std::function<void(int index)>& responder_main);
/// Pings (`round` with 50 ms) until every responder answers, as they subscribe one by one;
/// throws BenchError when a child in `children` exits first ("<what> (pid N) ... before
/// answering") or after 10 s ("<silent> never answered a ping within 10 s<hint>").
void await_responders(const std::function<bool(int timeout_ms)>& round, std::vector<pid_t>& children,
                      const std::string& what, const std::function<std::string()>& silent, const std::string& hint);
/// Times opt.warmup + opt.rounds calls of `round` (one ping, true once every responder has
/// answered within the timeout it is given in milliseconds) into `result`'s median, p90, min
/// and max; a round not answered counts in result.lost_rounds, and more than 1 % of them (at
/// least 10) throws BenchError "<what>: N rounds lost<detail()>" (round_trips.cpp).
void time_rounds(const Options& opt, const std::function<bool(int timeout_ms)>& round, const std::string& what,
                 FloorResult& result, const std::function<std::string()>& detail = {});
/// Sends the responders' stop (`send_stop`, again every 20 ms: a datagram may be lost) until
/// every child in `children` has exited, for 2 s at most; throws BenchError naming `what` for
/// a child that failed or for those that ignored the stop.
void stop_responders(std::vector<pid_t>& children, const std::function<void()>& send_stop, const std::string& what);

/// Round trip from one ping to all `responders` pongs, over forked responder processes.
FloorResult measure_floor(const Options& opt, int responders);
/// The same round trip over the match bus (bus_floor.cpp): the ping on the match lane, the
/// pongs on the robots' lane, tagged, each read in the caller's thread.
FloorResult measure_bus_floor(const Options& opt, int responders);
/// Real-time factor of sim_world + `robots` robot_shim processes in lockstep.
/// What authenticating the bus costs per lockstep frame (auth_cost.cpp), microseconds.
struct AuthCost {
  int robots = 0;
  size_t sense_bytes = 0, answer_bytes = 0;
  double seal_sense_us = 0, verify_sense_us = 0, seal_answer_us = 0, verify_answer_us = 0;
  double critical_path_us = 0; ///< added to one lockstep round (shims work side by side)
  double total_cpu_us = 0;     ///< summed over every process
};
AuthCost measure_auth_cost(int robots, int frames);

LockstepResult measure_lockstep(const Options& opt, int robots, const std::string& dir, double timeout_s);

}  // namespace touchline::bench
