#include "touchline/learning/multi_robot_sim.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "touchline/learning/observation.hpp"
#include "touchline/learning/pose_message.hpp"

namespace touchline::learning {

/// The behaviour a learner drives: each tick it returns the action set last, and sends its
/// pose estimate to its teammates whenever the radio's rate allows.
class MultiRobotSim::Commanded : public api::Behaviour {
 public:
  Commanded(float max_head_yaw_rad, int64_t message_gap_us)
      : max_head_yaw_rad_(max_head_yaw_rad), message_gap_us_(message_gap_us) {}

  AgentAction action;

  api::ActionCommand::All tick(const api::Blackboard& blackboard) override {
    api::ActionCommand::All request;
    if (action.kick_power > 0) {
      request.body.actionType = api::ActionCommand::ActionType::KICK;
      request.body.power = std::min(action.kick_power, 1.f);
      request.body.foot = blackboard.localisation.ballPosRR.heading > 0 ? api::ActionCommand::Foot::LEFT
                                                                        : api::ActionCommand::Foot::RIGHT;
    } else {
      request.body = api::ActionCommand::walk(action.forward_mm_s, action.left_mm_s, action.turn_rad_s);
    }
    request.head.yaw = std::clamp(action.head_yaw_rad, -max_head_yaw_rad_, max_head_yaw_rad_);
    if (last_sent_us_ < 0 || blackboard.utime - last_sent_us_ >= message_gap_us_) {
      request.teamMessage = encode_pose_message(blackboard.localisation.robotPos);
      last_sent_us_ = blackboard.utime;
    }
    return request;
  }

 private:
  float max_head_yaw_rad_;
  int64_t message_gap_us_;
  int64_t last_sent_us_ = -1;
};

namespace {
/// A non-finite number from a learner is no request: nothing (0) instead.
float finite(float v) { return std::isfinite(v) ? v : 0.f; }
} // namespace

MultiRobotSim::MultiRobotSim(MultiRobotDef def) : def_(std::move(def)) {
  sim::validate(def_.world);
  for (int team = 0; team < 2; ++team)
    for (int player = 1; player <= def_.world.match.team_size; ++player) ids_.push_back({team, player});
}

void MultiRobotSim::reset(uint64_t seed) {
  match_ = std::make_unique<inprocess::InProcessMatch>(def_.world, seed);
  drivers_.clear();
  // The radio's smallest gap between two messages, rounded up to whole microseconds.
  const auto gap_us = static_cast<int64_t>(std::ceil(1e6 / static_cast<double>(def_.world.comm.max_rate_hz)));
  for (const RobotId& id : ids_) {
    robot::RobotDef robot = def_.robot;
    robot.id = id;
    robot.behaviour = {"commanded", {}, {}}; // what the Blackboard says drives it: the learner
    auto driver = std::make_unique<Commanded>(robot.head.max_yaw_rad, gap_us);
    drivers_.push_back(driver.get());
    match_->add_robot(std::move(robot), std::move(driver));
  }
  match_->start();
  match_->step_frame(); // every robot standing: each Blackboard written, a first observation
  start_frame_ = match_->match().frame();
}

const inprocess::InProcessMatch& MultiRobotSim::match() const {
  if (!match_) throw std::logic_error("MultiRobotSim: reset() first");
  return *match_;
}

void MultiRobotSim::set_action(size_t index, const AgentAction& action) {
  match();
  drivers_.at(index)->action = {finite(action.forward_mm_s), finite(action.left_mm_s), finite(action.turn_rad_s),
                                finite(action.kick_power), finite(action.head_yaw_rad)};
}

void MultiRobotSim::step() {
  match();
  match_->step_frame();
}

int MultiRobotSim::observation_size() const { return learning::observation_size(def_.world.match.team_size); }

void MultiRobotSim::observe(size_t index, float* out) const {
  learning::observe(blackboard(index), def_.world.match.team_size, out);
}

const api::Blackboard& MultiRobotSim::blackboard(size_t index) const { return match().robot(ids_.at(index)).blackboard(); }

int64_t MultiRobotSim::frame() const { return match().match().frame() - start_frame_; }

} // namespace touchline::learning
