#pragma once
// Which LCM URL carries which channel. A match is configured with one URL (--lcm-url); on a
// udpm URL its messages travel on two ports of that one multicast group:
//
//  - the match port, the URL as given: everything the world publishes (TL_MATCH, TL_SENSE,
//    TL_TRUTH, TL_GAME, TL_STATUS, TL_EVENT, TL_JOIN_REPLY), heard by every robot and tool;
//  - the uplink port, the same URL with port + 1: everything a robot sends the world
//    (TL_ACT_<team>_<player>, TL_JOIN, TL_BLACKBOARD_<team>_<player>), which sim_world alone
//    joins (and tools/spy, and an lcm-logger started on it).
//
// Why: LCM's udpm receive thread reads every datagram sent to its port and only then drops
// the channels nobody subscribed to. On one port each of 8 robots' answers woke all 9
// processes of a match, 72 wake-ups a frame for the 8 the world needed (issue #14, item 3).
// The same group keeps the multicast routes of a multi-host match as they were.
//
// Other URLs (memq:// in tests, tcpq://, file://) carry both lanes on the one URL.
#include <string>

namespace touchline::transport {

enum class Lane {
  kMatch,  ///< the URL as given: what the world publishes
  kUplink, ///< robots to the world
};

/// The lane a channel travels on: kUplink for TL_ACT_*, TL_JOIN and TL_BLACKBOARD_*, and for
/// subscription patterns of those (a literal prefix then ".*": "TL_ACT_.*"); kMatch otherwise.
Lane lane_of(const std::string& channel);

struct LaneUrls {
  std::string match;  ///< the URL as given
  std::string uplink; ///< the robots' port: the same as `match` unless a udpm URL has room for it
  bool split() const { return match != uplink; }
  const std::string& of(Lane lane) const { return lane == Lane::kUplink ? uplink : match; }
};

/// The URLs of both lanes of a match run on `url`: for "udpm://GROUP:PORT?OPTIONS" the uplink
/// is "udpm://GROUP:PORT+1?OPTIONS" (group and options unchanged; "udpm://" alone is LCM's
/// 239.255.76.67:7667). Any other URL, and a udpm URL LCM would refuse or whose port
/// leaves no room above it, gives both lanes the one URL (lcm_url_problem() says why such
/// a udpm URL cannot be used).
LaneUrls lane_urls(const std::string& url);

} // namespace touchline::transport
