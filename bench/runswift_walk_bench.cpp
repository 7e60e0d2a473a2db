// touchline_runswift_walk_bench (built with -DTOUCHLINE_RUNSWIFT_DIR only): rUNSWift's walk
// through our adapter, open loop on the crude contact model of the walk's test
// (tests/robot_shim/runswift/open_loop_rig.hpp). For each request it crouches 1 s, walks
// 8 s and measures the last 4 s: the engine's own odometry speed, the body's speed by our
// forward kinematics from the stance sole, the support-switch (step) period and the swing
// height. Then what one step() costs: median and p99 over many ticks of steady walking.
// Usage: touchline_runswift_walk_bench [ticks for the cost, default 100000]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "open_loop_rig.hpp"

using namespace touchline::robot;
using runswift::testing::OpenLoopRig;
using Clock = std::chrono::steady_clock;

namespace {

nao::WalkCommand request(float forward_mm_s, float left_mm_s) {
  nao::WalkCommand c;
  c.kind = nao::WalkCommand::Kind::walk;
  c.forward_mm_s = forward_mm_s;
  c.left_mm_s = left_mm_s;
  return c;
}

void run(OpenLoopRig& rig, const nao::WalkCommand& c, double seconds) {
  const int ticks = static_cast<int>(seconds / runswift::testing::kDtS + 0.5);
  for (int i = 0; i < ticks; ++i) rig.tick(c);
}

void speeds(float forward_mm_s, float left_mm_s) {
  runswift::RunswiftWalk walk;
  OpenLoopRig rig(walk);
  nao::WalkCommand crouch;
  crouch.kind = nao::WalkCommand::Kind::crouch;
  run(rig, crouch, 1.0);
  run(rig, request(forward_mm_s, left_mm_s), 4.0);
  const double odo_f = rig.odometry_forward_mm, odo_l = rig.odometry_left_mm;
  const double body_f = rig.body_forward_mm, body_l = rig.body_left_mm, t0 = rig.time_s;
  const std::size_t first_switch = rig.switch_times_s.size();
  run(rig, request(forward_mm_s, left_mm_s), 4.0);
  const double span = rig.time_s - t0;
  double period = 0;
  const std::size_t n = rig.switch_times_s.size();
  if (n > first_switch + 1)
    period = (rig.switch_times_s[n - 1] - rig.switch_times_s[first_switch]) / static_cast<double>(n - 1 - first_switch);
  const bool sideways = forward_mm_s == 0;
  const double odo = sideways ? (rig.odometry_left_mm - odo_l) / span : (rig.odometry_forward_mm - odo_f) / span;
  const double body = sideways ? (rig.body_left_mm - body_l) / span : (rig.body_forward_mm - body_f) / span;
  std::printf("%-9s %6.0f  %9.1f  %9.1f  %7.3f  %8.3f  %6.1f  %d\n", sideways ? "left" : "forward",
              sideways ? left_mm_s : forward_mm_s, odo, body, period, n > first_switch ? period * 1e3 / 12.2 : 0.0,
              rig.max_swing_height_mm, rig.faults);
}

void cost(int ticks) {
  runswift::RunswiftWalk walk;
  OpenLoopRig rig(walk);
  nao::WalkCommand crouch;
  crouch.kind = nao::WalkCommand::Kind::crouch;
  run(rig, crouch, 1.0);
  const nao::WalkCommand c = request(200, 0);
  run(rig, c, 2.0);
  std::vector<double> step_us, tick_us;
  step_us.reserve(static_cast<std::size_t>(ticks));
  tick_us.reserve(static_cast<std::size_t>(ticks));
  nao::NaoSensorFrame s = rig.sensors();
  for (int i = 0; i < ticks; ++i) {
    // The engine alone: their kinematics, body model and walk, and our conversions.
    const auto a = Clock::now();
    const nao::NaoJointFrame out = walk.step(c, s);
    const auto b = Clock::now();
    s.joint_angles_rad = out.joint_angles_rad;
    step_us.push_back(std::chrono::duration<double, std::micro>(b - a).count());
    // With the rig's forward kinematics and contact model (what a simulator adds, roughly).
    const auto d = Clock::now();
    rig.tick(c);
    tick_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - d).count());
  }
  const auto pct = [](std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
  };
  std::printf("\ncost per tick over %d ticks of walking at 200 mm/s (us): step() median %.1f p99 %.1f; "
              "with the rig's kinematics and contact median %.1f p99 %.1f\n",
              ticks, pct(step_us, 0.5), pct(step_us, 0.99), pct(tick_us, 0.5), pct(tick_us, 0.99));
}

} // namespace

int main(int argc, char** argv) {
  const int ticks = argc > 1 ? std::atoi(argv[1]) : 100000;
  if (ticks <= 0) {
    std::fprintf(stderr, "touchline_runswift_walk_bench: ticks must be a positive number (got '%s')\n", argv[1]);
    return 2;
  }
  std::printf("rUNSWift Walk2014Generator, open loop, crude contact (1 s crouch, 4 s walking, then 4 s measured)\n");
  std::printf("%-9s %6s  %9s  %9s  %7s  %8s  %6s  %s\n", "request", "mm/s", "odometry", "kinematic", "step s",
              "ticks", "lift", "faults");
  for (float f : {100.f, 200.f, 300.f}) speeds(f, 0);
  for (float l : {100.f, 200.f}) speeds(0, l);
  cost(ticks);
  return 0;
}
