#include "touchline/lcm/lcm_url.hpp"

#include "touchline/lcm/lanes.hpp"

#include <arpa/inet.h>
#include <unistd.h>

#include <cstdio>
#include <sstream>

#include <lcm/lcm.h>

namespace touchline::transport {

namespace {

/// For udpm URLs ("udpm://GROUP:PORT?options"): a group that is an IPv4 address but no
/// multicast one. LCM's own message for it depends on the host's routes ("Invalid
/// argument" from setsockopt, or the 14 lines about multicast routes).
std::optional<std::string> not_a_group(const std::string& url) {
  for (const std::string scheme : {"udpm://", "mpudpm://"}) {
    if (url.rfind(scheme, 0) != 0) continue;
    const std::string rest = url.substr(scheme.size());
    const std::string host = rest.substr(0, rest.find_first_of(":?"));
    in_addr address{};
    if (host.empty() || inet_pton(AF_INET, host.c_str(), &address) != 1) return std::nullopt; // LCM says why
    if (!IN_MULTICAST(ntohl(address.s_addr)))
      return "not a multicast group address: " + host + " (udpm needs 224.0.0.0 to 239.255.255.255)";
  }
  return std::nullopt;
}

/// The line of LCM's output that says why: not its progress lines ("connecting..."), and
/// without its "Error: " prefix.
std::string reason_in(const std::string& printed) {
  if (printed.find("multicast route") != std::string::npos)
    return "no multicast route (on a machine without a network: ip route add 224.0.0.0/4 dev lo; "
           "see README, Networking)";
  std::istringstream lines(printed);
  for (std::string line; std::getline(lines, line);) {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (line.empty() || (line.size() >= 3 && line.compare(line.size() - 3, 3, "...") == 0)) continue;
    for (const char* prefix : {"Error: ", "Warning: "})
      if (line.rfind(prefix, 0) == 0) line.erase(0, std::string(prefix).size());
    return line;
  }
  return "LCM refused it";
}

/// Runs `open` with the process's stderr going to a temporary file; returns what was printed.
template <typename F>
std::string capturing_stderr(F open) {
  std::FILE* capture = std::tmpfile();
  if (!capture) { // nowhere to put it: let LCM print as it would
    open();
    return "";
  }
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  ::dup2(::fileno(capture), STDERR_FILENO);
  open();
  std::fflush(stderr);
  ::dup2(saved, STDERR_FILENO);
  ::close(saved);
  std::string printed;
  std::rewind(capture);
  char buffer[512];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, capture)) > 0;) printed.append(buffer, n);
  std::fclose(capture);
  return printed;
}

} // namespace

namespace {

std::optional<std::string> one_url_problem(const std::string& url) {
  if (auto problem = not_a_group(url)) return problem;
  bool opened = false;
  const std::string printed = capturing_stderr([&] {
    lcm_t* lcm = lcm_create(url.c_str());
    // A tcpq URL whose server cannot be reached still gives an lcm_t, with no descriptor.
    opened = lcm && lcm_get_fileno(lcm) >= 0;
    if (lcm) lcm_destroy(lcm);
  });
  // LCM warns and carries on with a default for an option value it cannot read
  // ("Invalid value for ttl"): a mistake all the same, and one that could widen the ttl.
  if (opened && printed.find("Warning") == std::string::npos) return std::nullopt;
  return reason_in(printed);
}

} // namespace

std::optional<std::string> lcm_url_problem(const std::string& url) {
  if (auto problem = one_url_problem(url)) return problem;
  const LaneUrls lanes = lane_urls(url);
  if (url.rfind("udpm://", 0) == 0 && !lanes.split())
    return "a udpm URL needs a port below 65534: the robots use the two ports above it (see README, Which port "
           "carries what)";
  if (!lanes.split()) return std::nullopt;
  for (const std::string& other : {lanes.uplink, lanes.robots})
    if (auto problem = one_url_problem(other)) return "the robots' port " + other + ": " + *problem;
  return std::nullopt;
}

} // namespace touchline::transport
