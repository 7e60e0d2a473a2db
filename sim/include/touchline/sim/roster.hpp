#pragma once
// Which shim plays which robot. A join claims (team, player) with a random instance id;
// the first claimant wins, a second is refused while the first is active, and a robot
// that timed out may be taken over by a new instance (a restarted shim).
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "touchline/frame.hpp"

namespace touchline::sim {

struct JoinReply {
  bool accepted = false;
  std::string reason; ///< one line, empty when accepted
};

struct Member {
  int64_t instance = 0;
  int pid = 0;
  bool active = true;        ///< answering frames; false after a timeout
  int64_t frames_answered = 0;
  int64_t frames_missed = 0;       ///< frames the world stepped without this robot's answer
  int64_t answered_frame = -1;     ///< the last frame whose answer was taken (-1: none)
  int64_t behaviour_cpu_us_sum = 0; ///< over answered frames
  int64_t behaviour_cpu_us_max = 0;
  int64_t behaviour_cpu_us_mean() const { return frames_answered ? behaviour_cpu_us_sum / frames_answered : 0; }
  int64_t localisation_frames = 0;    ///< answered frames on the field (not serving a penalty)
  double localisation_sq_mm_sum = 0;  ///< squared position error of the robot's belief, over those frames
  double localisation_sq_rad_sum = 0; ///< squared heading error
  double localisation_rms_mm() const;
  double localisation_rms_rad() const;
};

class Roster {
 public:
  explicit Roster(int team_size) : team_size_(team_size) {}

  JoinReply join(RobotId id, int64_t instance, int pid);
  /// The member playing `id`, if any.
  Member* find(RobotId id);
  const Member* find(RobotId id) const;
  const std::map<RobotId, Member>& members() const { return members_; }
  int team_size() const { return team_size_; }

 private:
  int team_size_;
  std::map<RobotId, Member> members_;
};

/// "team 0 player 2": how robots are named in messages to the user.
std::string describe(RobotId id);

} // namespace touchline::sim
