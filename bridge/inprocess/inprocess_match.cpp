#include "touchline/inprocess/inprocess_match.hpp"

#include <chrono>
#include <stdexcept>

namespace touchline::inprocess {

namespace {
constexpr int64_t kInstance = 1; // one process: every robot is its own only claimant
using Clock = std::chrono::steady_clock;

int64_t ns_since(Clock::time_point t0) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
}

/// The few dimensions of the world's field that the robot's landmark map needs.
robot::localisation::FieldMap field_map(const sim::FieldDef& field) {
  return {field.length_mm, field.width_mm, field.goal_width_mm, field.penalty_mark_distance_mm};
}
} // namespace

robot::Robot& InProcessMatch::add_robot(robot::RobotDef def, std::unique_ptr<api::Behaviour> behaviour) {
  const sim::JoinReply reply = match_.join(def.id, kInstance + static_cast<int64_t>(robots_.size()), 0);
  if (!reply.accepted) throw std::invalid_argument(reply.reason);
  def.localisation.filters.field = field_map(match_.config().field);
  robots_.push_back(std::make_unique<robot::Robot>(std::move(def), std::move(behaviour)));
  return *robots_.back();
}

void InProcessMatch::step_frame() {
  auto t0 = Clock::now();
  const SenseFrame frame = match_.sense();
  world_ns_ += ns_since(t0);
  acts_.clear();
  for (size_t i = 0; i < robots_.size(); ++i) {
    robot::Robot& robot = *robots_[i];
    const RobotSense* sense = frame.find(robot.id());
    if (!sense) continue;
    acts_.push_back(robot.step(frame, *sense));
    t0 = Clock::now();
    match_.apply(acts_.back(), kInstance + static_cast<int64_t>(i));
    world_ns_ += ns_since(t0);
  }
  t0 = Clock::now();
  match_.advance();
  world_ns_ += ns_since(t0);
}

void InProcessMatch::run_to_end() {
  while (!match_.finished()) step_frame();
}

robot::Robot& InProcessMatch::robot(RobotId id) {
  return const_cast<robot::Robot&>(static_cast<const InProcessMatch&>(*this).robot(id));
}

const robot::Robot& InProcessMatch::robot(RobotId id) const {
  for (const auto& robot : robots_)
    if (robot->id() == id) return *robot;
  throw std::out_of_range("no robot " + std::to_string(id.team) + "/" + std::to_string(id.player));
}

} // namespace touchline::inprocess
