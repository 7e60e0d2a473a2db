#include "touchline/lcm/bus.hpp"

#include <lcm/lcm.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <poll.h>

#include <cerrno>
#include <optional>
#include <regex>
#include <stdexcept>

#include "touchline/lcm/udpm_receiver.hpp"

namespace touchline::transport {

namespace {

/// A subscription's channel pattern, matched as LCM matches it (the whole name against the
/// regular expression), with the two forms the programs use taken without a regex.
class ChannelPattern {
 public:
  explicit ChannelPattern(const std::string& pattern) : text_(pattern) {
    const auto literal = [](const std::string& s) { return s.find_first_of(".[]{}()\\*+?|^$") == std::string::npos; };
    if (literal(pattern)) {
      kind_ = Kind::kExact;
    } else if (pattern.size() >= 2 && pattern.compare(pattern.size() - 2, 2, ".*") == 0 &&
               literal(pattern.substr(0, pattern.size() - 2))) {
      kind_ = Kind::kPrefix;
      text_.resize(pattern.size() - 2);
    } else {
      kind_ = Kind::kRegex;
      regex_ = std::regex(pattern);
    }
  }
  bool matches(const std::string& channel) const {
    switch (kind_) {
      case Kind::kExact: return channel == text_;
      case Kind::kPrefix: return channel.compare(0, text_.size(), text_) == 0;
      case Kind::kRegex: return std::regex_match(channel, regex_);
    }
    return false;
  }

 private:
  enum class Kind { kExact, kPrefix, kRegex } kind_ = Kind::kExact;
  std::string text_;
  std::regex regex_;
};

lcm_t* open_lcm(const std::string& url) {
  lcm_t* lcm = lcm_create(url.c_str());
  if (!lcm)
    throw std::runtime_error("cannot open LCM at " + url + " (is a multicast route on lo? see README, Networking)");
  return lcm;
}

} // namespace

struct Bus::Subscription {
  Bus* bus = nullptr;
  Handler handler;
  lcm_t* lcm = nullptr;                       ///< LCM dispatches it (a lane LCM reads) ...
  lcm_subscription_t* c_subscription = nullptr;
  std::optional<ChannelPattern> pattern;      ///< ... or the bus does (a lane it reads itself)
};

struct Bus::LaneState {
  std::string url;
  lcm_t* lcm = nullptr;
  std::unique_ptr<UdpmReceiver> receiver;     ///< made on the first subscription, on udpm
  std::vector<Subscription*> subscriptions;   ///< those the receiver's messages go to
  bool hears = false;
  ~LaneState() {
    if (lcm) lcm_destroy(lcm);
  }
};

Bus::Bus(const std::string& url, MatchKey key, Reporter report, BusRole role)
    : key_(std::move(key)), report_(std::move(report)), urls_(lane_urls(url)), role_(role) {
  for (const std::string& lane_url : urls_.split() ? std::vector<std::string>{urls_.match, urls_.uplink, urls_.robots}
                                                   : std::vector<std::string>{urls_.match}) {
    auto lane = std::make_unique<LaneState>();
    lane->url = lane_url;
    lane->lcm = open_lcm(lane_url);
    lanes_.push_back(std::move(lane));
  }
}

Bus::~Bus() {
  // The subscriptions' C callbacks point into this object: unsubscribe before freeing.
  for (auto& subscription : subscriptions_)
    if (subscription->c_subscription) lcm_unsubscribe(subscription->lcm, subscription->c_subscription);
}

Bus::LaneState& Bus::lane(Lane lane) const {
  return *lanes_[urls_.split() ? static_cast<size_t>(lane) : 0];
}

void Bus::subscribe(const std::string& channel_regex, Handler handler) {
  LaneState& on = lane(role_ == BusRole::kRobot && to_robots(channel_regex) ? Lane::kRobots : lane_of(channel_regex));
  auto subscription = std::make_unique<Subscription>();
  subscription->bus = this;
  subscription->handler = std::move(handler);
  if (is_udpm_url(on.url)) {
    try {
      subscription->pattern.emplace(channel_regex);
    } catch (const std::regex_error&) {
      throw std::runtime_error("cannot subscribe to " + channel_regex);
    }
    if (!on.receiver) on.receiver = std::make_unique<UdpmReceiver>(on.url);
    on.subscriptions.push_back(subscription.get());
  } else {
    subscription->lcm = on.lcm;
    subscription->c_subscription = lcm_subscribe(
        on.lcm, channel_regex.c_str(),
        [](const lcm_recv_buf_t* rbuf, const char* channel, void* user) { on_message(rbuf, channel, user); },
        subscription.get());
    if (!subscription->c_subscription) throw std::runtime_error("cannot subscribe to " + channel_regex);
  }
  on.hears = true;
  subscriptions_.push_back(std::move(subscription));
}

void Bus::on_message(const void* rbuf, const char* channel, void* user) {
  // A C callback: nothing may unwind out of here into liblcm.
  auto* subscription = static_cast<Subscription*>(user);
  const auto* buffer = static_cast<const lcm_recv_buf_t*>(rbuf);
  try {
    subscription->bus->dispatch(*subscription, channel, static_cast<const uint8_t*>(buffer->data),
                                buffer->data_size);
  } catch (...) {
    ++subscription->bus->counters_.handler_failures;
  }
}

void Bus::dispatch(Subscription& subscription, const std::string& channel, const uint8_t* wire, size_t size) {
  if (!verify(channel, wire, size)) {
    ++counters_.unauthenticated;
    if (report_) report_(channel + ": dropped a message without a valid tag (" + std::to_string(size) + " bytes)");
    return;
  }
  try {
    subscription.handler(BusMessage{channel, wire, size - kTagBytes, wire, size});
  } catch (const std::exception& e) {
    ++counters_.handler_failures;
    if (report_) report_(channel + ": handler failed: " + e.what());
  } catch (...) {
    ++counters_.handler_failures;
    if (report_) report_(channel + ": handler failed");
  }
}

void Bus::tag(const std::string& channel, const uint8_t* payload, size_t size, uint8_t* out) const {
  // HMAC over channel, a zero byte and the payload: a tag made for one channel is no good on
  // another, so a robot's act cannot be replayed as another robot's.
  std::vector<uint8_t> text(channel.begin(), channel.end());
  text.push_back(0);
  text.insert(text.end(), payload, payload + size);
  unsigned length = 0;
  if (!HMAC(EVP_sha256(), key_.bytes().data(), static_cast<int>(key_.bytes().size()), text.data(), text.size(), out,
            &length) ||
      length != kTagBytes)
    throw std::runtime_error("HMAC-SHA-256 failed");
}

std::vector<uint8_t> Bus::seal(const std::string& channel, const uint8_t* payload, size_t size) const {
  std::vector<uint8_t> wire(size + kTagBytes);
  std::copy(payload, payload + size, wire.begin());
  tag(channel, payload, size, wire.data() + size);
  return wire;
}

bool Bus::verify(const std::string& channel, const uint8_t* wire, size_t size) const {
  if (size < kTagBytes) return false;
  uint8_t expected[kTagBytes];
  tag(channel, wire, size - kTagBytes, expected);
  return CRYPTO_memcmp(expected, wire + size - kTagBytes, kTagBytes) == 0;
}

std::vector<uint8_t> Bus::publish(const std::string& channel, const uint8_t* payload, size_t size) {
  std::vector<uint8_t> wire = seal(channel, payload, size);
  publish_sealed(channel, wire);
  return wire;
}

void Bus::publish_sealed(const std::string& channel, const std::vector<uint8_t>& wire) {
  const auto send = [&](Lane on) {
    if (lcm_publish(lane(on).lcm, channel.c_str(), wire.data(), static_cast<unsigned>(wire.size())) != 0)
      throw std::runtime_error("cannot send on " + channel + " (" + std::to_string(wire.size()) + " bytes)");
  };
  if (urls_.split() && to_robots(channel)) send(Lane::kRobots); // the robots first: they wait for it
  send(lane_of(channel));
}

bool Bus::handle(int timeout_ms) {
  pollfd fds[2];
  LaneState* heard[2];
  nfds_t count = 0;
  for (auto& lane : lanes_) {
    if (!lane->hears) continue;
    heard[count] = lane.get();
    fds[count] = {lane->receiver ? lane->receiver->fd() : lcm_get_fileno(lane->lcm), POLLIN, 0};
    if (fds[count].fd < 0) throw std::runtime_error("LCM failed while receiving");
    ++count;
  }
  int ready = ::poll(fds, count, timeout_ms);
  while (ready < 0 && errno == EINTR) ready = ::poll(fds, count, timeout_ms);
  if (ready < 0) throw std::runtime_error("LCM failed while receiving");
  bool handled = false;
  for (nfds_t i = 0; i < count; ++i) {
    if (!(fds[i].revents & POLLIN)) continue;
    if (heard[i]->receiver) {
      handled = receive_all(*heard[i]) || handled;
    } else {
      if (lcm_handle(heard[i]->lcm) < 0) throw std::runtime_error("LCM failed while receiving");
      handled = true;
    }
  }
  return handled;
}

bool Bus::receive_all(LaneState& lane) {
  bool handled = false;
  UdpmReceiver::Message message{};
  std::string channel;
  // The subscriptions are those of this moment: a handler that subscribes adds to the vector.
  const size_t subscriptions = lane.subscriptions.size();
  while (lane.receiver->receive(message)) {
    channel.assign(message.channel);
    for (size_t i = 0; i < subscriptions; ++i) {
      Subscription& subscription = *lane.subscriptions[i];
      if (!subscription.pattern->matches(channel)) continue;
      dispatch(subscription, channel, message.data, message.size);
      handled = true;
    }
  }
  return handled;
}

void Bus::drain() {
  while (handle(0)) {
  }
}

} // namespace touchline::transport
