#include "touchline/learning/single_robot_sim.hpp"

#include <stdexcept>

#include "touchline/behaviour/registry.hpp"

namespace touchline::learning {

/// The behaviour a learner drives: it returns whatever command was set last.
class SingleRobotSim::Commanded : public api::Behaviour {
 public:
  api::ActionCommand::All command;
  api::ActionCommand::All tick(const api::Blackboard&) override { return command; }
};

namespace {
sim::WorldConfig learning_world(sim::WorldConfig world) {
  world.rules.referee = false;          // the game stays PLAYING: no kick-off, no penalties
  world.match.team_size = 1;
  world.match.duration_s = 1e9f;        // episodes end when the learner says so
  sim::validate(world);
  return world;
}
} // namespace

robot::RobotDef default_learning_robot() {
  robot::RobotDef def;
  def.localisation.perfect = true;
  return def;
}

Pose2D default_ball_spot(const sim::FieldDef& field) {
  return {-(0.5f * field.length_mm + 0.5f * field.border_mm), -(0.5f * field.width_mm + 0.5f * field.border_mm), 0};
}

SingleRobotSim::SingleRobotSim(SingleRobotDef def) : def_(std::move(def)) { def_.world = learning_world(def_.world); }

void SingleRobotSim::reset(uint64_t seed, const Pose2D& pose, std::optional<Pose2D> ball,
                           std::optional<robot::BehaviourDef> behaviour) {
  match_ = std::make_unique<inprocess::InProcessMatch>(def_.world, seed);
  commanded_ = nullptr;
  robot::RobotDef robot = def_.robot;
  std::unique_ptr<api::Behaviour> driver;
  if (behaviour) {
    robot.behaviour = std::move(*behaviour);
    driver = behaviour::make_behaviour(robot.behaviour.name, robot.behaviour.params);
  } else {
    robot.behaviour = {"commanded", {}, {}}; // what the Blackboard says drives it: the learner
    auto commanded = std::make_unique<Commanded>();
    commanded_ = commanded.get();
    driver = std::move(commanded);
  }
  match_->add_robot(std::move(robot), std::move(driver));
  match_->start();
  sim::World& world = match_->match().world();
  world.place_robot(0, pose);
  const Pose2D ball_spot = ball ? *ball : default_ball_spot(def_.world.field);
  world.place_ball(ball_spot.x_mm, ball_spot.y_mm);
  start_frame_ = match_->match().frame();
}

inprocess::InProcessMatch& SingleRobotSim::match() const {
  if (!match_) throw std::logic_error("SingleRobotSim: reset() first");
  return *match_;
}

void SingleRobotSim::step(const api::ActionCommand::Body& body) {
  inprocess::InProcessMatch& m = match();
  if (!commanded_) throw std::logic_error("SingleRobotSim: a behaviour drives this robot; call step_behaviour()");
  commanded_->command.body = body;
  m.step_frame();
}

void SingleRobotSim::step_behaviour() {
  inprocess::InProcessMatch& m = match();
  if (commanded_) throw std::logic_error("SingleRobotSim: no behaviour given to reset(); call step(command)");
  m.step_frame();
}

Pose2D SingleRobotSim::pose() const { return match().match().world().robot(0).body; }
sim::BallTruth SingleRobotSim::ball() const { return match().match().world().ball(); }
const robot::WalkRequest& SingleRobotSim::walk_velocity() const {
  return match().robot(def_.robot.id).motion().walk().velocity();
}
const api::Blackboard& SingleRobotSim::blackboard() const { return match().robot(def_.robot.id).blackboard(); }
int64_t SingleRobotSim::frame() const { return match().match().frame() - start_frame_; }
double SingleRobotSim::time_s() const {
  const sim::Match& m = match().match();
  return 1e-6 * static_cast<double>(frame_start_utime(m.frame()) - frame_start_utime(start_frame_));
}
uint64_t SingleRobotSim::state_hash() const { return match().match().world().state_hash(); }

} // namespace touchline::learning
