// The cost of authenticating the match bus (bus.hpp: HMAC-SHA-256 tag on every message), per
// lockstep frame: the world seals the sense, each shim verifies it and seals its answer, the
// world verifies every answer. Measured in process on encodings the size of a 4 v 4 frame.
#include <chrono>
#include <vector>

#include "bench.hpp"
#include "touchline/lcm/bus.hpp"
#include "touchline/lcm/codec.hpp"

namespace touchline::bench {

namespace {

std::vector<uint8_t> encoded(const auto& msg) {
  std::vector<uint8_t> bytes(static_cast<size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

} // namespace

AuthCost measure_auth_cost(int robots, int frames) {
  SenseFrame frame; // every robot seeing eight things and hearing one team message
  frame.motion_ticks = 4;
  for (int i = 0; i < robots; ++i) {
    RobotSense sense;
    sense.id = {i % 2, 1 + i / 2};
    sense.seen.assign(8, Observation{});
    sense.messages.push_back({1, 0, std::vector<uint8_t>(64, 7)});
    frame.robots.push_back(sense);
  }
  RobotAct act;
  act.motion_ticks = 4;
  act.team_message.assign(64, 7);
  const std::vector<uint8_t> sense = encoded(transport::to_lcm(frame));
  const std::vector<uint8_t> answer = encoded(transport::to_lcm(act, 0, 1));

  transport::Bus bus("memq://", transport::MatchKey::random());
  using Clock = std::chrono::steady_clock;
  const auto time_us = [&](auto&& work) {
    const auto t0 = Clock::now();
    bool ok = true;
    for (int f = 0; f < frames; ++f) ok &= work();
    if (!ok) throw BenchError("a tag did not verify");
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / frames;
  };
  std::vector<uint8_t> sense_wire, answer_wire;
  AuthCost cost;
  cost.robots = robots;
  cost.sense_bytes = sense.size();
  cost.answer_bytes = answer.size();
  cost.seal_sense_us = time_us([&] { sense_wire = bus.seal("TL_SENSE", sense.data(), sense.size()); return true; });
  cost.verify_sense_us = time_us([&] { return bus.verify("TL_SENSE", sense_wire.data(), sense_wire.size()); });
  cost.seal_answer_us = time_us([&] { answer_wire = bus.seal("TL_ACT_0_1", answer.data(), answer.size()); return true; });
  cost.verify_answer_us = time_us([&] { return bus.verify("TL_ACT_0_1", answer_wire.data(), answer_wire.size()); });
  // The shims verify and answer side by side; the world seals once and verifies every answer.
  cost.critical_path_us = cost.seal_sense_us + cost.verify_sense_us + cost.seal_answer_us + robots * cost.verify_answer_us;
  cost.total_cpu_us = cost.seal_sense_us + robots * (cost.verify_sense_us + cost.seal_answer_us + cost.verify_answer_us);
  return cost;
}

} // namespace touchline::bench
