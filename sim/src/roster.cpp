#include "touchline/sim/roster.hpp"

#include <cmath>

namespace touchline::sim {

double Member::localisation_rms_mm() const {
  return localisation_frames ? std::sqrt(localisation_sq_mm_sum / static_cast<double>(localisation_frames)) : 0;
}

double Member::localisation_rms_rad() const {
  return localisation_frames ? std::sqrt(localisation_sq_rad_sum / static_cast<double>(localisation_frames)) : 0;
}

std::string describe(RobotId id) {
  return "team " + std::to_string(id.team) + " player " + std::to_string(id.player);
}

JoinReply Roster::join(RobotId id, int64_t instance, int pid) {
  if (id.team != 0 && id.team != 1)
    return {false, "team " + std::to_string(id.team) + " does not exist (teams are 0 and 1)"};
  if (id.player < 1 || id.player > team_size_)
    return {false, "player " + std::to_string(id.player) + " is not in a team of " +
                       std::to_string(team_size_) + " (players 1.." + std::to_string(team_size_) + ")"};
  auto it = members_.find(id);
  if (it == members_.end()) {
    Member member;
    member.instance = instance;
    member.pid = pid;
    members_[id] = member;
    return {true, ""};
  }
  Member& member = it->second;
  if (member.instance == instance) return {true, ""}; // a repeated request: our reply was lost
  if (member.active)
    return {false, describe(id) + " is already played by another robot_shim (pid " +
                       std::to_string(member.pid) + ")"};
  member.instance = instance; // a restarted shim takes over a robot that timed out
  member.pid = pid;
  return {true, ""};
}

Member* Roster::find(RobotId id) {
  auto it = members_.find(id);
  return it == members_.end() ? nullptr : &it->second;
}

const Member* Roster::find(RobotId id) const {
  auto it = members_.find(id);
  return it == members_.end() ? nullptr : &it->second;
}

} // namespace touchline::sim
