#pragma once
// Whether LCM can open a provider URL, asked once before a program starts its work, so
// that a bad --lcm-url is one line naming the URL and the reason. LCM's C library prints
// its own diagnostics to stderr instead: for a udpm URL without a multicast route, 14
// lines of advice about ifconfig and route; for an unreachable tcpq server, three lines
// per connection attempt and then an abort (it hands select() the descriptor -1).
#include <optional>
#include <string>

namespace touchline::transport {

/// nullopt when LCM opens `url` (and, for udpm, the robots' port above it: lanes.hpp) and has
/// a descriptor to wait on; otherwise why not, in
/// one line: "not a multicast group address: 8.8.8.8 (udpm needs 224.0.0.0 to
/// 239.255.255.255)", "no multicast route (on a machine without a network: ip route add
/// 224.0.0.0/4 dev lo; see README, Networking)", "LCM provider \"bogus\" not found". What
/// LCM prints meanwhile is captured, not shown: call this before the program starts other
/// threads, since it redirects the process's stderr for that moment.
std::optional<std::string> lcm_url_problem(const std::string& url);

} // namespace touchline::transport
