#pragma once
// Which LCM URL carries which channel. A match is configured with one URL (--lcm-url); on a
// udpm URL its messages travel on three ports of that one multicast group:
//
//  - the match port, the URL as given: everything the world publishes (TL_MATCH, TL_SENSE,
//    TL_TRUTH, TL_GAME, TL_STATUS, TL_EVENT, TL_JOIN_REPLY), for every tool (the viewer,
//    the launcher, lcm-spy, lcm-logger); the world itself listens to none of it;
//  - the uplink port, the URL's port + 1: everything a robot sends the world
//    (TL_ACT_<team>_<player>, TL_JOIN, TL_BLACKBOARD_<team>_<player>), which sim_world
//    joins (and tools/spy --text, and an lcm-logger started on it);
//  - the robots' port, the URL's port + 2: a second copy of what a robot needs from the
//    world (TL_SENSE, TL_GAME, TL_JOIN_REPLY), the only port a robot joins.
//
// Why: a process is woken by every datagram sent to a port it joined, whatever the channel
// (LCM filters channels in user space). On one port each of 8 robots' answers and the
// world's truth woke all 9 processes of a match, about 90 wake-ups a frame where 16 are
// needed (issue #14, item 3). The same group keeps a multi-host match's routes as they were;
// the copies cost the world one more send per frame.
//
// Other URLs (memq:// in tests, tcpq://, file://) carry every lane on the one URL.
#include <string>

namespace touchline::transport {

enum class Lane {
  kMatch,  ///< the URL as given: what the world publishes, for the tools
  kUplink, ///< robots to the world
  kRobots, ///< the world to the robots: copies of TL_SENSE, TL_GAME, TL_JOIN_REPLY
};

/// The lane a robot's message travels on: kUplink for TL_ACT_*, TL_JOIN and TL_BLACKBOARD_*,
/// and for subscription patterns of those (a literal prefix then ".*": "TL_ACT_.*"); kMatch
/// for everything else.
Lane lane_of(const std::string& channel);
/// Whether the world sends `channel` to the robots on kRobots as well as on kMatch:
/// TL_SENSE, TL_GAME and TL_JOIN_REPLY.
bool to_robots(const std::string& channel);

struct LaneUrls {
  std::string match;  ///< the URL as given
  std::string uplink; ///< the robots' answers: the same as `match` unless a udpm URL has room
  std::string robots; ///< what the robots hear: likewise
  bool split() const { return match != uplink; }
  const std::string& of(Lane lane) const {
    return lane == Lane::kUplink ? uplink : lane == Lane::kRobots ? robots : match;
  }
};

/// The URLs of the lanes of a match run on `url`: for "udpm://GROUP:PORT?OPTIONS" the uplink
/// is "udpm://GROUP:PORT+1?OPTIONS" and the robots' "udpm://GROUP:PORT+2?OPTIONS" (group and
/// options unchanged; "udpm://" alone is LCM's 239.255.76.67:7667). Any other URL, and a
/// udpm URL LCM would refuse or whose port leaves no room above it, gives every lane the one
/// URL (lcm_url_problem() says why such a udpm URL cannot be used).
LaneUrls lane_urls(const std::string& url);

} // namespace touchline::transport
