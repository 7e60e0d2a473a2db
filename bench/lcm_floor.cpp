// touchline_bench, part 1: the LCM round-trip floor with N responder processes.
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/types.h>
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

#include "bench.hpp"

namespace touchline::bench {


/// A responder process: answers each ping on its own pong channel until told to stop.
class Responder {
public:
  Responder(lcm::LCM& lcm, int index) : lcm_(lcm), pong_channel_(kPongPrefix + std::to_string(index)) {}

  void on_ping(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    lcm_.publish(pong_channel_, rbuf->data, rbuf->data_size);  // echo the 8-byte sequence number
  }
  void on_stop(const lcm::ReceiveBuffer*, const std::string&) { stop = true; }

  bool stop = false;

private:
  lcm::LCM& lcm_;
  std::string pong_channel_;
};

[[noreturn]] void responder_main(const std::string& url, int index, pid_t parent) {
  if (!die_with_parent(parent)) _exit(3);
  int code = 0;
  {
    lcm::LCM lcm(url);
    if (!lcm.good()) _exit(4);
    Responder responder(lcm, index);
    lcm.subscribe(kPingChannel, &Responder::on_ping, &responder);
    lcm.subscribe(kStopChannel, &Responder::on_stop, &responder);
    while (!responder.stop) {
      if (lcm.handleTimeout(200) < 0) {
        code = 5;
        break;
      }
    }
  }
  _exit(code);
}

/// The parent's side: counts the pongs for the sequence number in flight.
class PongCounter {
public:
  explicit PongCounter(int responders) : seen_(static_cast<size_t>(responders), false) {}

  void expect(uint64_t seq) {
    seq_ = seq;
    std::fill(seen_.begin(), seen_.end(), false);
    count_ = 0;
  }
  void on_pong(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
    uint64_t seq = 0;
    if (rbuf->data_size != sizeof seq) return;
    std::memcpy(&seq, rbuf->data, sizeof seq);
    if (seq != seq_) return;  // a late answer to an earlier (lost) round
    const size_t index = std::strtoul(channel.c_str() + std::strlen(kPongPrefix), nullptr, 10);
    if (index >= seen_.size() || seen_[index]) return;
    seen_[index] = true;
    ++count_;
  }
  bool all() const { return count_ == seen_.size(); }
  std::string missing() const {
    std::string s;
    for (size_t i = 0; i < seen_.size(); ++i)
      if (!seen_[i]) s += (s.empty() ? "" : ",") + std::to_string(i);
    return s;
  }

private:
  uint64_t seq_ = 0;
  std::vector<bool> seen_;
  size_t count_ = 0;
};

/// Publishes ping seq and handles messages until all pongs for it came or timeout_ms passed.
bool ping_round(lcm::LCM& lcm, PongCounter& counter, uint64_t seq, int timeout_ms) {
  counter.expect(seq);
  if (lcm.publish(kPingChannel, &seq, sizeof seq) != 0) throw BenchError("LCM publish failed");
  const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!counter.all()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    if (lcm.handleTimeout(static_cast<int>(left)) < 0) throw BenchError("LCM handle failed");
  }
  return true;
}

FloorResult measure_floor(const Options& opt, int responders) {
  const pid_t parent = getpid();
  std::vector<pid_t> children = fork_responders(responders, [&](int i) { responder_main(opt.lcm_url, i, parent); });
  const auto cleanup = [&] {
    for (pid_t pid : children) kill_and_reap(pid);
    children.clear();
  };

  FloorResult result;
  result.responders = responders;
  try {
    lcm::LCM lcm(opt.lcm_url);
    if (!lcm.good()) throw BenchError("cannot open LCM at " + opt.lcm_url);
    PongCounter counter(responders);
    lcm.subscribe(std::string(kPongPrefix) + ".*", &PongCounter::on_pong, &counter);

    // Until every responder has subscribed (answers), keep pinging; 10 s at most.
    uint64_t seq = 1;
    const auto round = [&](int timeout_ms) { return ping_round(lcm, counter, seq++, timeout_ms); };
    await_responders(
        round, children, "LCM responder",
        [&] { return "LCM responders " + counter.missing() + " of " + std::to_string(responders); },
        " (is multicast routed on lo? run through bench/run or tools/netns)");

    time_rounds(opt, round, "LCM round trip", result,
                [&] { return " (responders " + counter.missing() + " silent for 1 s)"; });
    // Stop the responders (resent in case a datagram is lost).
    const char stop = 1;
    stop_responders(children, [&] { lcm.publish(kStopChannel, &stop, 1); }, "LCM responder");
  } catch (...) {
    cleanup();
    throw;
  }
  return result;
}


}  // namespace touchline::bench
