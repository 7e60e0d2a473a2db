// touchline_bench, part 1b: the round-trip floor over the match bus itself (bridge/lcm
// bus.hpp), the transport lockstep runs on: the ping sent as the sense is (on the robots'
// port, then the match port), each pong on the answers' port (lanes.hpp), every message
// tagged, each lane read in the caller's thread. LCM's floor (lcm_floor.cpp) is the cap issue #14 states its goal
// against; this one says how much of the frame the bus leaves to the world and the robots.
#include <sys/types.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "touchline/lcm/bus.hpp"

#include "bench.hpp"

namespace touchline::bench {

namespace {

using transport::Bus;
using transport::BusMessage;
using transport::MatchKey;

constexpr const char* kBusPing = "TL_SENSE";           // to the robots' lane and the match lane
constexpr const char* kBusStop = "TL_GAME";            // as the end of a match
constexpr const char* kBusPongPrefix = "TL_ACT_9_";    // the robots' lane, as an answer

[[noreturn]] void bus_responder_main(const std::string& url, const MatchKey& key, int index, pid_t parent) {
  if (!die_with_parent(parent)) _exit(3);
  int code = 0;
  try {
    Bus bus(url, key, {}, transport::BusRole::kRobot);
    const std::string pong = kBusPongPrefix + std::to_string(index);
    bool stop = false;
    bus.subscribe(kBusPing, [&](const BusMessage& m) { bus.publish(pong, m.payload, m.payload_size); });
    bus.subscribe(kBusStop, [&](const BusMessage&) { stop = true; });
    while (!stop) bus.handle(200);
  } catch (...) {
    code = 5;
  }
  _exit(code);
}

} // namespace

FloorResult measure_bus_floor(const Options& opt, int responders) {
  const MatchKey key = MatchKey::random();
  const pid_t parent = getpid();
  std::vector<pid_t> children =
      fork_responders(responders, [&](int i) { bus_responder_main(opt.lcm_url, key, i, parent); });
  const auto cleanup = [&] {
    for (pid_t pid : children) kill_and_reap(pid);
    children.clear();
  };
  FloorResult result;
  result.responders = responders;
  try {
    Bus bus(opt.lcm_url, key);
    uint64_t seq = 0;
    std::vector<bool> seen(static_cast<size_t>(responders));
    int count = 0;
    bus.subscribe(std::string(kBusPongPrefix) + ".*", [&](const BusMessage& m) {
      uint64_t got = 0;
      if (m.payload_size != sizeof got) return;
      std::memcpy(&got, m.payload, sizeof got);
      const size_t index = std::strtoul(m.channel.c_str() + std::strlen(kBusPongPrefix), nullptr, 10);
      if (got != seq || index >= seen.size() || seen[index]) return;
      seen[index] = true;
      ++count;
    });
    const auto round = [&](int timeout_ms) {
      ++seq;
      std::fill(seen.begin(), seen.end(), false);
      count = 0;
      bus.publish(kBusPing, reinterpret_cast<const uint8_t*>(&seq), sizeof seq);
      const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
      while (count < responders) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return false;
        bus.handle(static_cast<int>(left));
      }
      return true;
    };
    await_responders(round, children, "bus responder", [] { return std::string("bus responders"); }, "");
    time_rounds(opt, round, "bus round trip", result);
    const uint8_t stop = 1;
    stop_responders(children, [&] { bus.publish(kBusStop, &stop, 1); }, "bus responder");
  } catch (...) {
    cleanup();
    throw;
  }
  return result;
}

} // namespace touchline::bench
