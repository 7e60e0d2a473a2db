#pragma once
// TilePolicy: a learned go-to-pose policy read from a policy file (format v1,
// docs/learning/policy_format.md): a tile-coded Q-function over the robot-relative target
// and a table of walk actions, acted on greedily. The port of behaviour_py/skills/tile_policy.py.
//
// All arithmetic is in double and written in the order the format gives, as the Python
// original does, so both pick the same action every frame.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "touchline/robot_api/geometry.hpp"

namespace touchline::behaviour::skills {

inline constexpr const char* POLICY_MAGIC = "touchline-policy";  ///< first word of a policy file ...
inline constexpr int POLICY_VERSION = 1;                          ///< ... and the format version after it
inline constexpr const char* DEFAULT_POLICY = "policies/go_to_pose.policy"; ///< the trained policy, data-relative
inline constexpr const char* FEATURES_POLAR_LOG = "polar-log";    ///< the one feature kind of version 1
inline constexpr int U_TILING_OFFSET = 1;        ///< tiling k is offset by k * this / tilings of a tile along u ...
inline constexpr int B_TILING_OFFSET = 3;        ///< ... along the bearing ...
inline constexpr int H_TILING_OFFSET = 5;        ///< ... and along the heading error
inline constexpr int MAX_POLICY_WEIGHTS = 10000000; ///< more is not a policy this reader should hold in memory

/// angle in [-pi, pi), in double (the format's h): the robot API's wrap, named as in
/// tile_policy.py.
using api::wrapAngle;

/// One action of the policy: a walk request.
struct WalkAction {
  double forward = 0; ///< mm/s
  double left = 0;    ///< mm/s
  double turn = 0;    ///< rad/s
};

/// What a policy file says, checked.
struct TilePolicyDef {
  std::string name;              ///< the file, for messages
  double distanceScale = 100;    ///< mm: S of u = log(1 + d / S)
  double maxDistance = 12000;    ///< mm: u is clamped at log(1 + maxDistance / S)
  int tilings = 1;               ///< K
  int tilesU = 1, tilesB = 1, tilesH = 1; ///< tiles along u (Tu + 1 cells), bearing, heading error
  double successDistance = 0;    ///< mm: stand within this ...
  double successHeading = 0;     ///< rad: ... and this
  std::vector<WalkAction> actions;
  std::vector<double> weights;   ///< K * (Tu + 1) * Tb * Th * actions
};

class TilePolicy {
 public:
  explicit TilePolicy(TilePolicyDef def);

  /// Per tiling k, the weight index of action 0: (((k (Tu+1) + iu) Tb + ib) Th + ih) A.
  std::vector<size_t> cellIndices(double x, double y, double theta) const;
  /// Q(s, a) for every action a, summed over the tilings in order.
  std::vector<double> values(double x, double y, double theta) const;
  /// argmax_a Q(s, a), ties to the lowest index.
  size_t greedyAction(double x, double y, double theta) const;
  /// Within the success tolerances: the skill stands.
  bool arrived(double x, double y, double theta) const;

  const TilePolicyDef& def() const { return def_; }
  const std::vector<WalkAction>& actions() const { return def_.actions; }

 private:
  TilePolicyDef def_;
  double uMax_;
};

/// The TilePolicy in `text`; name (the file) prefixes every error. Throws BehaviourError.
TilePolicy parsePolicy(const std::string& text, const std::string& name);
/// The TilePolicy in the file `path`. Throws BehaviourError.
TilePolicy loadPolicy(const std::string& path);
/// loadPolicy(path), read once per path: skills are made often (params change, roles), the
/// file is parsed once. Thread-safe.
std::shared_ptr<const TilePolicy> cachedPolicy(const std::string& path);

} // namespace touchline::behaviour::skills
