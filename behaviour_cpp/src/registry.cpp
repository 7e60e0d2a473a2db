#include "touchline/behaviour/registry.hpp"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "touchline/behaviour/skills/go_to_ball.hpp"
#include "touchline/behaviour/skills/go_to_pose.hpp"
#include "touchline/behaviour/skills/head_scan.hpp"
#include "touchline/behaviour/skills/learned_go_to_pose.hpp"
#include "touchline/behaviour/skills/line_up_and_kick.hpp"
#include "touchline/behaviour/skills/look_for_ball.hpp"
#include "touchline/behaviour/skills/skill_behaviour.hpp"
#include "touchline/behaviour/skills/stand.hpp"
#include "touchline/behaviour/skills/team.hpp"
#include "touchline/behaviour/skills/track_ball.hpp"
#include "touchline/behaviour/walk_skills.hpp"

namespace touchline::behaviour {

namespace {

constexpr const char* WALKER_HAND = "hand";       ///< walker=hand: GoToPose walks to the ball (the default)
constexpr const char* WALKER_LEARNED = "learned"; ///< walker=learned: LearnedGoToPose with the policy file "policy"

/// Reads numeric parameters, rejecting unknown keys and malformed numbers.
class ParamReader {
 public:
  ParamReader(const std::string& behaviour, const Params& params) : behaviour_(behaviour), params_(params) {}

  float number(const std::string& key, float fallback) {
    known_.insert(key);
    const auto it = params_.find(key);
    if (it == params_.end()) return fallback;
    char* end = nullptr;
    const float value = std::strtof(it->second.c_str(), &end);
    if (it->second.empty() || *end != '\0' || !std::isfinite(value))
      throw BehaviourError(behaviour_ + ": parameter " + key + " must be a number (got '" + it->second + "')");
    return value;
  }

  /// A number in double, as Python reads it (float(text)): for the learned walker's target,
  /// which must be the same bits in both ports.
  double real(const std::string& key, double fallback) {
    known_.insert(key);
    const auto it = params_.find(key);
    if (it == params_.end()) return fallback;
    char* end = nullptr;
    const double value = std::strtod(it->second.c_str(), &end);
    if (it->second.empty() || *end != '\0' || !std::isfinite(value))
      throw BehaviourError(behaviour_ + ": parameter " + key + " must be a number (got '" + it->second + "')");
    return value;
  }

  /// A number read as a switch: nonzero is on (as behaviour.py's ParamReader.flag).
  bool flag(const std::string& key) { return number(key, 0) != 0; }

  std::optional<std::string> text(const std::string& key) {
    known_.insert(key);
    const auto it = params_.find(key);
    if (it == params_.end()) return std::nullopt;
    return it->second;
  }

  /// The policy file the learned walker uses (walker=learned; policy=..., data-relative), or
  /// nullopt for GoToPose (walker=hand, the default).
  std::optional<std::string> walker() {
    const std::string walker = text("walker").value_or(WALKER_HAND);
    if (walker != WALKER_HAND && walker != WALKER_LEARNED)
      throw BehaviourError(behaviour_ + ": parameter walker must be " + WALKER_HAND + " or " + WALKER_LEARNED +
                           " (got '" + walker + "')");
    const std::optional<std::string> policy = text("policy");
    if (walker == WALKER_HAND) {
      if (policy) throw BehaviourError(behaviour_ + ": parameter policy needs walker=" + WALKER_LEARNED);
      return std::nullopt;
    }
    return policy.value_or(skills::DEFAULT_POLICY);
  }

  /// The SupporterDef the team's midfielder and defender play: supporters=tuned (the default)
  /// or thesis (Algorithms 4.1 and 4.2 with the thesis's numbers), as behaviour.py's.
  const skills::SupporterDef& supporters() {
    const std::vector<std::string>& names = skills::supporterDefNames();
    const std::string name = text("supporters").value_or(names.front());
    if (const skills::SupporterDef* found = skills::supporterDef(name)) return *found;
    std::string choices;
    for (const std::string& known : names) choices += (choices.empty() ? "" : " or ") + known;
    throw BehaviourError(behaviour_ + ": parameter supporters must be " + choices + " (got '" + name + "')");
  }

  void reject_unknown() const {
    for (const auto& [key, value] : params_)
      if (!known_.count(key)) throw BehaviourError(behaviour_ + ": unknown parameter '" + key + "'");
  }

 private:
  std::string behaviour_;
  const Params& params_;
  std::set<std::string> known_;
};

/// A skill as behaviour.py runs it: the body skill with LookForBall (or the given head) and LEDs.
template <typename Head = skills::LookForBall>
std::unique_ptr<api::Behaviour> with_head(std::unique_ptr<api::Behaviour> body) {
  return std::make_unique<skills::SkillBehaviour>(std::move(body), std::make_unique<Head>());
}

/// The team behaviour playing `role` (ROLE_NONE: roles from team messages), with its parameters.
std::unique_ptr<api::Behaviour> team(int role, ParamReader& p) {
  const std::optional<std::string> policy = p.walker();
  return std::make_unique<skills::Team>(role, policy, p.supporters());
}

struct Entry {
  const char* name;
  std::string help;
  std::function<std::unique_ptr<api::Behaviour>(ParamReader&)> make;
};

const std::vector<Entry>& entries() {
  static const std::string walkerHelp =
      "walker (hand: GoToPose walks to the ball; learned: the learned policy does), policy (with walker=learned: its "
      "file in the data directory, default policies/go_to_pose.policy)";
  static const std::string teamHelp =
      walkerHelp + ", supporters (tuned: the midfielder's and defender's tuned numbers, the default; thesis: "
                   "Algorithms 4.1 and 4.2 as the thesis wrote them)";
  static const std::vector<Entry> all = {
      {"stand", "stands still", [](ParamReader&) { return std::make_unique<skills::Stand>(); }},
      {"walk", "walks at a constant velocity: forward (mm/s), left (mm/s), turn (rad/s)",
       [](ParamReader& p) {
         const float forward = p.number("forward", 0), left = p.number("left", 0), turn = p.number("turn", 0);
         return std::make_unique<ConstantWalk>(forward, left, turn);
       }},
      {"goto", "walks to a field pose and stands (GoToPose, head still): x (mm), y (mm), theta (rad)",
       [](ParamReader& p) {
         const float x = p.number("x", 0), y = p.number("y", 0), theta = p.number("theta", 0);
         return std::make_unique<skills::GoToPose>(x, y, theta); // the skill, head still
       }},
      // The skills, named and parameterised as in behaviour_py/behaviour.py.
      {"GoToPose",
       "thesis Algorithm 4.3 with forward-first, head looking for the ball: x (mm), y (mm), theta (rad), "
       "face_ball (1: end facing the ball instead of theta)",
       [](ParamReader& p) {
         const float x = p.number("x", 0), y = p.number("y", 0), theta = p.number("theta", 0);
         return with_head(std::make_unique<skills::GoToPose>(x, y, theta, p.flag("face_ball")));
       }},
      {"LearnedGoToPose",
       "walks to a field pose with a learned policy, head looking for the ball: x (mm), y (mm), theta (rad), "
       "policy (file in the data directory, default policies/go_to_pose.policy)",
       [](ParamReader& p) {
         const double x = p.real("x", 0), y = p.real("y", 0), theta = p.real("theta", 0);
         const std::string policy = p.text("policy").value_or(skills::DEFAULT_POLICY);
         return with_head(std::make_unique<skills::LearnedGoToPose>(x, y, theta, policy));
       }},
      {"GoToBall",
       std::string("walks behind the ball facing the goal: goal_x (mm), goal_y (mm), behind (mm), ") + walkerHelp,
       [](ParamReader& p) {
         const float goalX = p.number("goal_x", skills::OPPONENT_GOAL_X);
         const float goalY = p.number("goal_y", skills::OPPONENT_GOAL_Y);
         const float behind = p.number("behind", skills::BEHIND_BALL_DIST);
         return with_head(std::make_unique<skills::GoToBall>(goalX, goalY, behind, p.walker()));
       }},
      {"LineUpAndKick",
       std::string("approaches the ball, lines up and kicks at the goal: goal_x (mm), goal_y (mm), dribble (1: "
                   "dribble), power (0..1), ") + walkerHelp,
       [](ParamReader& p) {
         const float goalX = p.number("goal_x", skills::OPPONENT_GOAL_X);
         const float goalY = p.number("goal_y", skills::OPPONENT_GOAL_Y);
         const bool dribble = p.flag("dribble");
         const float power = p.number("power", dribble ? skills::DRIBBLE_POWER : skills::KICK_POWER);
         return with_head(std::make_unique<skills::LineUpAndKick>(goalX, goalY, dribble, power, p.walker()));
       }},
      {"TrackBall", "stands, head pointed at the ball",
       [](ParamReader&) { return with_head<skills::TrackBall>(std::make_unique<skills::Stand>()); }},
      {"HeadScan", "stands, head sweeping side to side",
       [](ParamReader&) { return with_head<skills::HeadScan>(std::make_unique<skills::Stand>()); }},
      // The team and its roles: whole behaviours (head, LEDs, team messages, game states).
      // walker=learned: the striker walks to the ball with the learned policy.
      {"Team", std::string("plays a match: roles (goalie, striker, defender, midfielder) from team messages; ") + teamHelp,
       [](ParamReader& p) { return team(skills::ROLE_NONE, p); }},
      {"Goalie", std::string("plays a match as goalie; ") + teamHelp,
       [](ParamReader& p) { return team(skills::ROLE_GOALIE, p); }},
      {"Striker", std::string("plays a match as striker; ") + teamHelp,
       [](ParamReader& p) { return team(skills::ROLE_STRIKER, p); }},
      {"Midfielder", std::string("plays a match as midfielder (thesis Algorithm 4.1); ") + teamHelp,
       [](ParamReader& p) { return team(skills::ROLE_MIDFIELDER, p); }},
      {"Defender", std::string("plays a match as defender (thesis Algorithm 4.2); ") + teamHelp,
       [](ParamReader& p) { return team(skills::ROLE_DEFENDER, p); }},
  };
  return all;
}

} // namespace

std::unique_ptr<api::Behaviour> make_behaviour(const std::string& name, const Params& params) {
  for (const auto& entry : entries()) {
    if (name != entry.name) continue;
    ParamReader reader(name, params);
    auto behaviour = entry.make(reader);
    reader.reject_unknown();
    return behaviour;
  }
  std::string names;
  for (const auto& entry : entries()) names += std::string(names.empty() ? "" : ", ") + entry.name;
  throw BehaviourError("unknown behaviour '" + name + "' (known: " + names + ")");
}

std::vector<std::pair<std::string, std::string>> behaviour_help() {
  std::vector<std::pair<std::string, std::string>> help;
  for (const auto& entry : entries()) help.emplace_back(entry.name, entry.help);
  return help;
}

} // namespace touchline::behaviour
