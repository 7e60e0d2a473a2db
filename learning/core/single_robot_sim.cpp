#include "touchline/learning/single_robot_sim.hpp"

#include <stdexcept>

namespace touchline::learning {

/// The behaviour a learner drives: it returns whatever command was set last.
class SingleRobotSim::Commanded : public api::Behaviour {
 public:
  api::ActionCommand::All command;
  api::ActionCommand::All tick(const api::Blackboard&) override { return command; }
};

namespace {
constexpr RobotId kRobot{0, 1};

sim::WorldConfig learning_world(sim::WorldConfig world) {
  world.rules.referee = false;          // the game stays PLAYING: no kick-off, no penalties
  world.match.team_size = 1;
  world.match.duration_s = 1e9f;        // episodes end when the learner says so
  sim::validate(world);
  return world;
}
} // namespace

Pose2D default_ball_spot(const sim::FieldDef& field) {
  return {-(0.5f * field.length_mm + 0.5f * field.border_mm), -(0.5f * field.width_mm + 0.5f * field.border_mm), 0};
}

SingleRobotSim::SingleRobotSim(SingleRobotDef def) : def_(std::move(def)) { def_.world = learning_world(def_.world); }

void SingleRobotSim::reset(uint64_t seed, const Pose2D& pose, std::optional<Pose2D> ball,
                           std::unique_ptr<api::Behaviour> behaviour) {
  match_ = std::make_unique<inprocess::InProcessMatch>(def_.world, seed);
  commanded_ = nullptr;
  if (!behaviour) {
    auto commanded = std::make_unique<Commanded>();
    commanded_ = commanded.get();
    behaviour = std::move(commanded);
  }
  robot::LocalisationModeDef localisation;
  localisation.perfect = def_.perfect_localisation;
  match_->add_robot(kRobot, def_.walk, std::move(behaviour), localisation);
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
  return match().robot(kRobot).motion().walk().velocity();
}
const api::Blackboard& SingleRobotSim::blackboard() const { return match().robot(kRobot).blackboard(); }
int64_t SingleRobotSim::frame() const { return match().match().frame() - start_frame_; }
double SingleRobotSim::time_s() const {
  const sim::Match& m = match().match();
  return 1e-6 * static_cast<double>(frame_start_utime(m.frame()) - frame_start_utime(start_frame_));
}
uint64_t SingleRobotSim::state_hash() const { return match().match().world().state_hash(); }

} // namespace touchline::learning
