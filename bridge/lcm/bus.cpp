#include "touchline/lcm/bus.hpp"

#include <lcm/lcm.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <poll.h>

#include <cerrno>
#include <stdexcept>

namespace touchline::transport {

struct Bus::Subscription {
  Bus* bus = nullptr;
  Handler handler;
  lcm_t* lcm = nullptr;
  lcm_subscription_t* c_subscription = nullptr;
};

namespace {

lcm_t* open_lcm(const std::string& url) {
  lcm_t* lcm = lcm_create(url.c_str());
  if (!lcm)
    throw std::runtime_error("cannot open LCM at " + url + " (is a multicast route on lo? see README, Networking)");
  return lcm;
}

} // namespace

Bus::Bus(const std::string& url, MatchKey key, Reporter report)
    : key_(std::move(key)), report_(std::move(report)), urls_(lane_urls(url)), match_(open_lcm(urls_.match)) {
  if (!urls_.split()) {
    uplink_ = match_;
    return;
  }
  try {
    uplink_ = open_lcm(urls_.uplink);
  } catch (...) {
    lcm_destroy(match_);
    throw;
  }
}

Bus::~Bus() {
  // The subscriptions' C callbacks point into this object: unsubscribe before freeing.
  for (auto& subscription : subscriptions_) lcm_unsubscribe(subscription->lcm, subscription->c_subscription);
  if (uplink_ != match_) lcm_destroy(uplink_);
  lcm_destroy(match_);
}

void Bus::subscribe(const std::string& channel_regex, Handler handler) {
  const Lane on = lane_of(channel_regex);
  auto subscription = std::make_unique<Subscription>();
  subscription->bus = this;
  subscription->handler = std::move(handler);
  subscription->lcm = lane(on);
  subscription->c_subscription = lcm_subscribe(
      subscription->lcm, channel_regex.c_str(),
      [](const lcm_recv_buf_t* rbuf, const char* channel, void* user) { on_message(rbuf, channel, user); },
      subscription.get());
  if (!subscription->c_subscription) throw std::runtime_error("cannot subscribe to " + channel_regex);
  subscriptions_.push_back(std::move(subscription));
  (on == Lane::kUplink && urls_.split() ? hears_uplink_ : hears_match_) = true;
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
  if (lcm_publish(lane(lane_of(channel)), channel.c_str(), wire.data(), static_cast<unsigned>(wire.size())) != 0)
    throw std::runtime_error("cannot send on " + channel + " (" + std::to_string(wire.size()) + " bytes)");
}

bool Bus::handle(int timeout_ms) {
  if (!(hears_match_ && hears_uplink_)) {
    // One lane heard (or none yet: the match lane, as a bus of one URL always did). LCM
    // waits on it itself.
    const int status = lcm_handle_timeout(hears_uplink_ ? uplink_ : match_, timeout_ms);
    if (status < 0) throw std::runtime_error("LCM failed while receiving");
    return status > 0;
  }
  // Both lanes (a tool's or a test's bus): wait on both, dispatch what is waiting on each.
  pollfd fds[2] = {{lcm_get_fileno(match_), POLLIN, 0}, {lcm_get_fileno(uplink_), POLLIN, 0}};
  int ready = ::poll(fds, 2, timeout_ms);
  while (ready < 0 && errno == EINTR) ready = ::poll(fds, 2, timeout_ms);
  if (ready < 0) throw std::runtime_error("LCM failed while receiving");
  bool handled = false;
  for (int i = 0; i < 2; ++i) {
    if (!(fds[i].revents & POLLIN)) continue;
    if (lcm_handle(i == 0 ? match_ : uplink_) < 0) throw std::runtime_error("LCM failed while receiving");
    handled = true;
  }
  return handled;
}

void Bus::drain() {
  while (handle(0)) {
  }
}

} // namespace touchline::transport
