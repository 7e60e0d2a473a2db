#include "touchline/lcm/lanes.hpp"

#include <cstdlib>

namespace touchline::transport {

namespace {

constexpr const char* kUdpm = "udpm://";
/// LCM's group and port for "udpm://" with nothing after it.
constexpr const char* kLcmDefaultNetwork = "239.255.76.67:7667";

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

} // namespace

Lane lane_of(const std::string& channel) {
  // Prefixes, so that a subscription pattern lands where its channels do. TL_JOIN_REPLY is
  // the world's answer: on the match port with the rest of what the world says.
  if (channel == "TL_JOIN" || starts_with(channel, "TL_ACT_") || starts_with(channel, "TL_BLACKBOARD_"))
    return Lane::kUplink;
  return Lane::kMatch;
}

bool to_robots(const std::string& channel) {
  return channel == "TL_SENSE" || channel == "TL_GAME" || channel == "TL_JOIN_REPLY";
}

LaneUrls lane_urls(const std::string& url) {
  LaneUrls urls{url, url, url};
  if (!starts_with(url, kUdpm)) return urls;
  const size_t options_at = url.find('?');
  std::string network = url.substr(7, options_at == std::string::npos ? std::string::npos : options_at - 7);
  const std::string options = options_at == std::string::npos ? "" : url.substr(options_at);
  if (network.empty()) network = kLcmDefaultNetwork;
  const size_t colon = network.find(':');
  if (colon == std::string::npos) return urls; // no port: LCM's own choice; nothing to add one to
  // As LCM reads it (strtol, base 0); a port it would refuse is left for lcm_url_problem().
  const std::string port_text = network.substr(colon + 1);
  char* end = nullptr;
  const long port = std::strtol(port_text.c_str(), &end, 0);
  if (end == port_text.c_str() || *end != '\0' || port < 1 || port > 65535 - 2) return urls;
  urls.uplink = kUdpm + network.substr(0, colon) + ":" + std::to_string(port + 1) + options;
  urls.robots = kUdpm + network.substr(0, colon) + ":" + std::to_string(port + 2) + options;
  return urls;
}

} // namespace touchline::transport
