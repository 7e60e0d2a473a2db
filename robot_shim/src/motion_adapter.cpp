#include "touchline/robot/motion_adapter.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "touchline/angles.hpp"
#include "touchline/robot/nao/inertial.hpp"
#include "touchline/robot/walk_cycle_engine.hpp"

#include "approach.hpp"

namespace touchline::robot {

namespace {

MotionDef with_head(const HeadDef& head) {
  MotionDef def;
  def.head = head;
  return def;
}

std::unique_ptr<WalkEngine> required(std::unique_ptr<WalkEngine> engine) {
  if (!engine) throw std::invalid_argument("MotionAdapter needs a walk engine");
  if (engine->period_us() <= 0)
    throw std::invalid_argument("walk engine " + engine->name() + ": control period must be > 0 us");
  return engine;
}

bool finite(const Pose2D& p) { return std::isfinite(p.x_mm) && std::isfinite(p.y_mm) && std::isfinite(p.theta_rad); }

Pose2D lerp(const Pose2D& a, const Pose2D& b, double t) {
  const auto mix = [t](float from, float to) { return static_cast<float>(from + (to - from) * t); };
  return {mix(a.x_mm, b.x_mm), mix(a.y_mm, b.y_mm),
          normalise_angle(static_cast<float>(a.theta_rad + normalise_angle(b.theta_rad - a.theta_rad) * t))};
}

Pose2D body_of(const FeetPose& feet) {
  return {0.5f * (feet.left.x_mm + feet.right.x_mm), 0.5f * (feet.left.y_mm + feet.right.y_mm),
          mean_heading(feet.left.theta_rad, feet.right.theta_rad)};
}
} // namespace

MotionAdapter::MotionAdapter(const WalkDef& walk, const HeadDef& head, const KickDef& kick)
    : MotionAdapter(std::make_unique<WalkCycleEngine>(walk, kick), with_head(head)) {}

MotionAdapter::MotionAdapter(std::unique_ptr<WalkEngine> engine, const MotionDef& def)
    : engine_(required(std::move(engine))), def_(def), period_us_(engine_->period_us()), joint_feet_(def.joint_feet) {
  engine_->start(output_);
  if (engine_->output_kind() == EngineOutputKind::kJoints) {
    sensors_.joints = output_.joints;
    joint_feet_.reset(output_.joints);
    current_ = {joint_feet_.feet(), body_of(joint_feet_.feet())};
  } else {
    current_ = {output_.feet, output_.odometry};
  }
  sensors_.fsr_kg = nao::foot_pressure(joint_feet_.stance(), def_.foot_pressure);
  previous_ = current_;
  feet_ = current_.feet;
  status_ = engine_->status();
}

const WalkCycle& MotionAdapter::walk() const {
  if (!engine_->gait()) throw std::logic_error("walk engine " + engine_->name() + " has no WalkCycle");
  return engine_->gait()->walk();
}

const KickGenerator& MotionAdapter::kick() const {
  if (!engine_->gait()) throw std::logic_error("walk engine " + engine_->name() + " has no KickGenerator");
  return engine_->gait()->kick();
}

void MotionAdapter::tick_head(const api::ActionCommand::Head& request) {
  const HeadDef& head = def_.head;
  float yaw = request.isRelative ? yaw_ + request.yaw : request.yaw;
  float pitch = request.isRelative ? pitch_ + request.pitch : request.pitch;
  yaw = std::clamp(yaw, -head.max_yaw_rad, head.max_yaw_rad);
  pitch = std::clamp(pitch, head.min_pitch_rad, head.max_pitch_rad);
  const float step = head.max_speed_rad_s * kMotionTick_s;
  yaw_ = approach(yaw_, yaw, step * std::clamp(request.yawSpeed, 0.01f, 1.f));
  pitch_ = approach(pitch_, pitch, step * std::clamp(request.pitchSpeed, 0.01f, 1.f));
}

bool MotionAdapter::accept(const WalkEngineOutput& out, Sample& sample) {
  std::string fault;
  if (engine_->output_kind() == EngineOutputKind::kJoints) {
    if (const auto bad = nao::check_joints(out.joints, def_.joint_tolerance_rad)) fault = *bad;
  } else if (!finite(out.feet.left) || !finite(out.feet.right) || !finite(out.odometry)) {
    fault = "feet or odometry not finite";
  }
  if (fault.empty()) {
    if (engine_->output_kind() == EngineOutputKind::kJoints) {
      // Position-controlled motors: the joints go where they were told, within their stops
      // and as fast as their motors turn.
      sensors_.joints = nao::follow(sensors_.joints, out.joints, static_cast<float>(period_us_) * 1e-6f);
      sample.feet = joint_feet_.update(sensors_.joints);
      sample.odometry = body_of(sample.feet);
    } else {
      sample = {out.feet, out.odometry};
    }
    return true;
  }
  std::ostream& warn = def_.warnings ? *def_.warnings : std::cerr;
  warn << "walk engine " << engine_->name() << ": " << fault << " at t=" << static_cast<double>(sample_us_) * 1e-6
       << " s: the robot stands from now on\n";
  stopped_ = true;
  return false;
}

void MotionAdapter::tick_engine(const api::ActionCommand::Body& body, bool fallen) {
  Sample next = current_; // standing: a stopped engine's feet stay where they are
  if (!stopped_) {
    const float turn = normalise_angle(current_.odometry.theta_rad - previous_.odometry.theta_rad);
    nao::set_inertial(sensors_, turn, static_cast<float>(period_us_) * 1e-6f, fallen);
    engine_->tick(body, sensors_, output_);
    if (accept(output_, next)) {
      status_ = engine_->status();
      sensors_.fsr_kg = nao::foot_pressure(joint_feet_.stance(), def_.foot_pressure);
    } else {
      status_ = WalkEngineStatus{};
    }
  }
  previous_ = current_;
  current_ = next;
  sample_us_ += period_us_;
  ++engine_ticks_;
}

MotionAdapter::Sample MotionAdapter::sample_at(int64_t utime) const {
  if (utime >= sample_us_) return current_; // on a sample (always, for a 10 ms engine)
  const double t = static_cast<double>(utime - (sample_us_ - period_us_)) / static_cast<double>(period_us_);
  return {{lerp(previous_.feet.left, current_.feet.left, t), lerp(previous_.feet.right, current_.feet.right, t)},
          lerp(previous_.odometry, current_.odometry, t)};
}

void MotionAdapter::placed() {
  if (engine_->output_kind() != EngineOutputKind::kFeet || stopped_) return;
  engine_->placed(output_);
  current_ = previous_ = {output_.feet, output_.odometry};
  feet_ = current_.feet;
  status_ = engine_->status();
}

TickMotion MotionAdapter::tick(api::Blackboard& blackboard) {
  const api::ActionCommand::All& request = blackboard.behaviour.request;
  tick_head(request.head);

  auto& motion = blackboard.motion;
  world_us_ += kMotionTickUs;
  while (sample_us_ < world_us_) tick_engine(request.body, motion.fallen);
  const Sample now = sample_at(world_us_);

  TickMotion out;
  feet_motion(feet_, now.feet, out.left, out.right);
  feet_ = now.feet;

  motion.active = status_.active;
  motion.kickPhase = status_.kick_phase;
  motion.odometry = {now.odometry.x_mm, now.odometry.y_mm, now.odometry.theta_rad};
  motion.headYaw = yaw_;
  motion.headPitch = pitch_;
  motion.standing = status_.standing;
  ++motion.ticks;
  return out;
}

} // namespace touchline::robot
