#include "touchline/learning/tile_q.hpp"

#include <cmath>
#include <stdexcept>

#include "touchline/angles.hpp"
#include "touchline/frame.hpp"
#include "touchline/random.hpp"

namespace touchline::learning {

TileQ::TileQ(const TileCodingDef& coding, std::vector<WalkAction> actions)
    : coding_(coding), actions_(std::move(actions)) {
  if (actions_.empty()) throw std::invalid_argument("TileQ needs at least one action");
  weights_.assign(coding_.cells() * actions_.size(), 0.f);
}

double TileQ::value(const std::vector<int>& cells, int action) const {
  double q = 0;
  for (int cell : cells) q += weights_[static_cast<size_t>(cell) * actions_.size() + static_cast<size_t>(action)];
  return q;
}

int TileQ::greedy(const std::vector<int>& cells) const {
  int best = 0;
  double best_q = value(cells, 0);
  for (int a = 1; a < action_count(); ++a) {
    const double q = value(cells, a);
    if (q > best_q) best = a, best_q = q;
  }
  return best;
}

int TileQ::greedy(double x_mm, double y_mm, double heading_rad) const {
  std::vector<int> cells(static_cast<size_t>(coding_.def().tilings));
  coding_.active(x_mm, y_mm, heading_rad, cells.data());
  return greedy(cells);
}

Pose2D relative_target(const Pose2D& pose, const Pose2D& target) {
  const double dx = target.x_mm - pose.x_mm, dy = target.y_mm - pose.y_mm;
  const double c = std::cos(pose.theta_rad), s = std::sin(pose.theta_rad);
  return {static_cast<float>(c * dx + s * dy), static_cast<float>(-s * dx + c * dy),
          normalise_angle(target.theta_rad - pose.theta_rad)};
}

bool reached(const Pose2D& relative, const EpisodeDef& episode) {
  return std::hypot(relative.x_mm, relative.y_mm) < episode.success_distance_mm &&
         std::abs(relative.theta_rad) < episode.success_heading_rad;
}

namespace {
void step(SingleRobotSim& sim, const WalkAction& a) {
  sim.step(api::ActionCommand::walk(a.forward_mm_s, a.left_mm_s, a.turn_rad_s));
}

/// The shaping potential in frames (see SarsaLambdaDef).
double potential(const SarsaLambdaDef& def, const Pose2D& relative) {
  if (def.shaping_forward_mm_s <= 0 || def.shaping_turn_rad_s <= 0) return 0;
  return -static_cast<double>(kFramesPerSecond) *
         std::hypot(std::hypot(relative.x_mm, relative.y_mm) / def.shaping_forward_mm_s,
                    relative.theta_rad / def.shaping_turn_rad_s);
}

std::vector<int> active_cells(const TileQ& q, const Pose2D& relative) {
  std::vector<int> cells(static_cast<size_t>(q.coding().def().tilings));
  q.coding().active(relative.x_mm, relative.y_mm, relative.theta_rad, cells.data());
  return cells;
}
} // namespace

EpisodeResult greedy_episode(const TileQ& q, SingleRobotSim& sim, const Pose2D& start, const Pose2D& target,
                             const EpisodeDef& episode, uint64_t sim_seed) {
  sim.reset(sim_seed, start);
  EpisodeResult result;
  Pose2D relative = relative_target(sim.pose(), target);
  while (!reached(relative, episode) && result.frames < episode.max_frames) {
    step(sim, q.actions()[static_cast<size_t>(q.greedy(active_cells(q, relative)))]);
    ++result.frames;
    relative = relative_target(sim.pose(), target);
  }
  result.success = reached(relative, episode);
  return result;
}

SarsaLambda::SarsaLambda(TileQ& q, const SarsaLambdaDef& def, uint64_t seed)
    : q_(q), def_(def), rng_(seed), trace_(q.weights().size(), 0.f) {}

int SarsaLambda::choose(const std::vector<int>& cells, double epsilon) {
  const int n = q_.action_count();
  if (uniform01(rng_) < epsilon) return static_cast<int>(uniform01(rng_) * n);
  int best = 0, ties = 0;
  double best_q = -1e300;
  for (int a = 0; a < n; ++a) {
    const double v = q_.value(cells, a);
    if (v > best_q) {
      best = a, best_q = v, ties = 1;
    } else if (v == best_q && uniform01(rng_) * ++ties < 1.0) {
      best = a; // reservoir draw: each tied action equally likely
    }
  }
  return best;
}

void SarsaLambda::decay_traces(double factor) {
  size_t kept = 0;
  for (int index : traced_) {
    float& e = trace_[static_cast<size_t>(index)];
    e = static_cast<float>(e * factor);
    if (e >= def_.trace_cutoff) traced_[kept++] = index;
    else e = 0;
  }
  traced_.resize(kept);
}

EpisodeResult SarsaLambda::episode(SingleRobotSim& sim, const Pose2D& start, const Pose2D& target, double epsilon,
                                   const EpisodeDef& episode, uint64_t sim_seed) {
  for (int index : traced_) trace_[static_cast<size_t>(index)] = 0;
  traced_.clear();
  sim.reset(sim_seed, start);
  const size_t actions = static_cast<size_t>(q_.action_count());
  const double step_size = def_.alpha / q_.coding().def().tilings;
  std::vector<float>& w = q_.weights();

  EpisodeResult result;
  Pose2D relative = relative_target(sim.pose(), target);
  if (reached(relative, episode)) return {0, true};
  std::vector<int> cells = active_cells(q_, relative);
  int action = choose(cells, epsilon);
  double before = potential(def_, relative);
  while (true) {
    step(sim, q_.actions()[static_cast<size_t>(action)]);
    ++result.frames;
    for (int cell : cells) {
      const int index = static_cast<int>(static_cast<size_t>(cell) * actions + static_cast<size_t>(action));
      if (trace_[static_cast<size_t>(index)] == 0) traced_.push_back(index);
      trace_[static_cast<size_t>(index)] = 1; // replacing trace
    }
    relative = relative_target(sim.pose(), target);
    result.success = reached(relative, episode);
    const double after = result.success ? 0.0 : potential(def_, relative);
    double delta = -1.0 + after - before - q_.value(cells, action); // reward -1 per frame, shaped
    int next_action = 0;
    std::vector<int> next_cells;
    if (!result.success) { // bootstrap, also at the time limit: truncation is not an end state
      next_cells = active_cells(q_, relative);
      next_action = choose(next_cells, epsilon);
      delta += def_.gamma * q_.value(next_cells, next_action);
    }
    for (int index : traced_) w[static_cast<size_t>(index)] += static_cast<float>(step_size * delta * trace_[static_cast<size_t>(index)]);
    if (result.success || result.frames >= episode.max_frames) break;
    decay_traces(def_.gamma * def_.lambda);
    cells = std::move(next_cells);
    action = next_action;
    before = after; // the next step starts where this one ended
  }
  return result;
}

} // namespace touchline::learning
