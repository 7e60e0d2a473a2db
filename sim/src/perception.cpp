#include "touchline/random.hpp"
#include "touchline/sim/perception.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "touchline/angles.hpp"
#include "touchline/sim/camera.hpp"
#include "touchline/sim/occlusion.hpp"

namespace touchline::sim {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

/// Adds bearing noise without touching an exact heading: normalise_angle's fmod would
/// change the low bits of an angle already in range, and zero noise must give the
/// geometry exactly.
float wrap_if_needed(float a) { return (a >= -kPi && a < kPi) ? a : normalise_angle(a); }

/// Standard normal (Box-Muller, one pair of draws per number).
double gaussian(KeyedDraws& draws) {
  const double u1 = 1.0 - uniform01(draws); // (0, 1]: log is finite
  const double u2 = uniform01(draws);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

uint32_t viewer_id(const Viewer& me) { return draw_id(me.id.team, me.id.player); }

} // namespace

Perception::Perception(const Field& field, const PerceptionDef& def, uint64_t seed)
    : field_(field), def_(def), landmarks_(field_landmarks(field_)), seed_(seed) {}

bool Perception::hidden(const Viewer& me, const std::vector<Viewer>& robots, float x_mm, float y_mm) const {
  for (const Viewer& other : robots) {
    if (other.id == me.id) continue;
    if (body_hides(me.body, other.body, def_.occluder_radius_mm, x_mm, y_mm)) return true;
  }
  return false;
}

bool Perception::consider(const Viewer& me, const std::vector<Viewer>& robots, int64_t frame, ObjectKind kind, int id,
                          float x_mm, float y_mm, float miss_probability, bool can_be_hidden,
                          std::vector<Observation>& out) const {
  const auto s = sight(def_.camera, me.body, me.head_yaw_rad, me.head_pitch_rad, x_mm, y_mm);
  if (!s) return false;
  if (can_be_hidden && hidden(me, robots, x_mm, y_mm)) return false;
  // This object's own draws: (kind, id) names it among everything this viewer may see.
  const auto object = (static_cast<uint32_t>(kind) << 16) | static_cast<uint32_t>(id);
  auto draws = keyed_draws(seed_, DrawStream::kCamera, frame, viewer_id(me), object);
  if (uniform01(draws) < miss_probability) return false;
  const double distance_z = gaussian(draws);
  const double bearing_z = gaussian(draws);

  const NoiseDef& n = def_.noise;
  const double distance = s->distance_mm;
  const double distance_sd = n.distance_sd_mm + n.distance_sd_fraction * distance;
  const double bearing_sd = n.bearing_sd_rad + n.bearing_sd_rad_per_m * distance / 1000.0;
  const auto bearing_error = static_cast<float>(bearing_sd * bearing_z);

  Observation o;
  o.kind = kind;
  o.id = id;
  o.distance_mm = std::max(0.f, s->distance_mm + static_cast<float>(distance_sd * distance_z));
  o.heading_rad = wrap_if_needed(s->heading_rad + bearing_error);
  // The image coordinate moves with the bearing (image_x grows to the left, like the
  // heading), clamped to the image: the object was in view.
  o.image_x = std::clamp(s->image_x + bearing_error / def_.camera.field_of_view_rad, 0.f, 1.f);
  out.push_back(o);
  return true;
}

std::vector<Observation> Perception::observe(const Viewer& me, const std::vector<Viewer>& robots,
                                             const BallTruth& ball, int64_t frame) const {
  const NoiseDef& n = def_.noise;
  std::vector<Observation> out;

  const bool ball_seen =
      consider(me, robots, frame, ObjectKind::kBall, 0, ball.x_mm, ball.y_mm, n.ball_miss_probability, true, out);
  auto phantom_draws = keyed_draws(seed_, DrawStream::kPhantomBall, frame, viewer_id(me));
  const double phantom = uniform01(phantom_draws);
  if (!ball_seen && phantom < n.phantom_ball_probability) {
    const double phantom_across = uniform01(phantom_draws);
    const double phantom_distance = uniform01(phantom_draws);
    // Somewhere in the image, at most as far as the camera sees: a plausible false
    // detection, which a ball filter must learn to distrust.
    const float range = std::min(n.phantom_ball_max_distance_mm,
                                 max_camera_distance(def_.camera, me.head_pitch_rad));
    const float fov = def_.camera.field_of_view_rad;
    Observation o;
    o.kind = ObjectKind::kBall;
    o.image_x = static_cast<float>(phantom_across);
    o.heading_rad = wrap_if_needed(me.head_yaw_rad + (o.image_x - 0.5f) * fov);
    o.distance_mm = static_cast<float>((1.0 - phantom_distance) * range); // (0, range]
    out.push_back(o);
  }

  for (const Landmark& mark : landmarks_)
    consider(me, robots, frame, mark.kind, mark.id, mark.x_mm, mark.y_mm, n.landmark_miss_probability, true, out);

  for (const Viewer& other : robots) {
    if (other.id == me.id) continue; // a robot never sees itself
    const ObjectKind kind = other.id.team == me.id.team ? ObjectKind::kTeammate : ObjectKind::kOpponent;
    // Robots are not occluded: a robot partly behind another still shows its head and arms.
    consider(me, robots, frame, kind, other.id.player, other.body.x_mm, other.body.y_mm, n.robot_miss_probability,
             false, out);
  }
  return out;
}

SonarReading Perception::sonar(const Viewer& me, const std::vector<Viewer>& robots, int64_t frame) const {
  SonarReading reading;
  for (const Viewer& other : robots) {
    if (other.id == me.id) continue;
    sonar_update(def_.sonar, me.body, other.body.x_mm, other.body.y_mm, reading);
  }
  if (def_.sonar_sees_goal_posts) {
    for (const Landmark& mark : landmarks_)
      if (mark.kind == ObjectKind::kGoalPost) sonar_update(def_.sonar, me.body, mark.x_mm, mark.y_mm, reading);
  }
  auto draws = keyed_draws(seed_, DrawStream::kSonar, frame, viewer_id(me));
  const double left_z = gaussian(draws), right_z = gaussian(draws);
  const double sd = def_.sonar_noise_sd_mm / static_cast<double>(def_.sonar.range_mm); // in fractions of the range
  auto noisy = [sd](float fraction, double z) {
    if (fraction >= 1.f) return fraction; // nothing seen: no echo to be noisy
    return std::clamp(fraction + static_cast<float>(sd * z), 0.f, 1.f);
  };
  reading.left = noisy(reading.left, left_z);
  reading.right = noisy(reading.right, right_z);
  return reading;
}

float Perception::gyro_turn(const Viewer& me, float turn_rad, int64_t frame) const {
  auto draws = keyed_draws(seed_, DrawStream::kInertial, frame, viewer_id(me));
  const double noise_rad = static_cast<double>(def_.gyro_turn_sd_rad) * gaussian(draws);
  return normalise_angle(static_cast<float>(static_cast<double>(turn_rad) + noise_rad));
}

Touch Perception::touch(const Viewer& me, const std::vector<Viewer>& robots) const {
  Touch touch;
  for (const Viewer& other : robots)
    if (other.id != me.id) touch_update(def_.touch, me.body, other.body.x_mm, other.body.y_mm, touch);
  for (const Landmark& mark : landmarks_)
    if (mark.kind == ObjectKind::kGoalPost) touch_post_update(def_.touch, me.body, mark.x_mm, mark.y_mm, touch);
  return touch;
}

std::vector<Percept> Perception::perceive(const std::vector<Viewer>& robots, const BallTruth& ball,
                                          int64_t frame) const {
  std::vector<Percept> percepts;
  percepts.reserve(robots.size());
  for (const Viewer& me : robots) {
    Percept p;
    p.id = me.id;
    p.seen = observe(me, robots, ball, frame);
    p.sonar = sonar(me, robots, frame);
    p.touch = touch(me, robots);
    percepts.push_back(std::move(p));
  }
  return percepts;
}

} // namespace touchline::sim
