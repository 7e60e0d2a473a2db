// The match bus over LCM's in-process transport (memq://, no network): messages carry a
// tag made with the match secret; anything without a valid one is dropped before a
// handler sees it; a handler that throws is counted and never unwinds into liblcm.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "touchline/lcm/bus.hpp"
#include "touchline/pose2d_t.hpp"

using namespace touchline;
using namespace touchline::transport;

namespace {

MatchKey key_of(char digit) { return MatchKey::from_hex(std::string(64, digit)); }

pose2d_t pose(float x_mm) {
  pose2d_t p;
  p.x_mm = x_mm;
  p.y_mm = 2;
  p.theta_rad = 0.5f;
  return p;
}

struct Received {
  std::vector<std::string> channels;
  std::vector<float> x_mm;
};

void listen(Bus& bus, const std::string& channels, Received& into) {
  bus.subscribe(channels, [&into](const BusMessage& m) {
    pose2d_t p;
    if (p.decode(m.payload, 0, static_cast<int>(m.payload_size)) < 0) throw std::runtime_error("cannot decode");
    into.channels.push_back(m.channel);
    into.x_mm.push_back(p.x_mm);
  });
}

} // namespace

TEST(Bus, DeliversWhatWasSentWithTheMatchSecret) {
  Bus bus("memq://", key_of('a'));
  Received got;
  listen(bus, "TL_.*", got);
  bus.publish("TL_POSE", pose(7));
  bus.drain();
  ASSERT_EQ(got.x_mm, std::vector<float>{7});
  EXPECT_EQ(got.channels, std::vector<std::string>{"TL_POSE"});
  EXPECT_EQ(bus.counters().unauthenticated, 0);
}

TEST(Bus, TheWireIsTheEncodingFollowedByItsTag) {
  Bus bus("memq://", key_of('a'));
  const pose2d_t p = pose(3);
  const std::vector<uint8_t> wire = bus.publish("TL_POSE", p);
  ASSERT_EQ(wire.size(), static_cast<size_t>(p.getEncodedSize()) + kTagBytes);
  pose2d_t decoded; // LCM's decoders read the encoding and ignore the tag after it
  ASSERT_GT(decoded.decode(wire.data(), 0, static_cast<int>(wire.size())), 0);
  EXPECT_EQ(decoded.x_mm, 3);
  EXPECT_TRUE(bus.verify("TL_POSE", wire.data(), wire.size()));
  EXPECT_FALSE(bus.verify("TL_OTHER", wire.data(), wire.size())); // a tag is good on its channel only
}

TEST(Bus, DropsMessagesWithoutAValidTagBeforeAnyHandler) {
  Bus bus("memq://", key_of('a'));
  Bus forger("memq://", key_of('b')); // memq is per instance: its bytes are re-sent on ours below
  Received got;
  std::vector<std::string> reports;
  Bus reporting("memq://", key_of('a'), [&reports](const std::string& line) { reports.push_back(line); });
  listen(reporting, "TL_.*", got);

  const pose2d_t p = pose(1);
  std::vector<uint8_t> encoding(static_cast<size_t>(p.getEncodedSize()));
  p.encode(encoding.data(), 0, static_cast<int>(encoding.size()));
  reporting.publish_sealed("TL_POSE", encoding);                                     // no tag at all
  reporting.publish_sealed("TL_POSE", forger.seal("TL_POSE", encoding.data(), encoding.size())); // another secret
  std::vector<uint8_t> flipped = bus.seal("TL_POSE", encoding.data(), encoding.size());
  flipped[2] ^= 1;                                                                       // changed in transit
  reporting.publish_sealed("TL_POSE", flipped);
  reporting.publish_sealed("TL_POSE", bus.seal("TL_OTHER", encoding.data(), encoding.size())); // lifted tag
  reporting.publish_sealed("TL_POSE", {});                                               // empty
  reporting.drain();

  EXPECT_TRUE(got.x_mm.empty());
  EXPECT_EQ(reporting.counters().unauthenticated, 5);
  ASSERT_EQ(reports.size(), 5u);
  EXPECT_NE(reports[0].find("TL_POSE: dropped a message without a valid tag"), std::string::npos) << reports[0];
}

TEST(Bus, AHandlerThatThrowsIsCountedAndTheBusGoesOn) {
  std::vector<std::string> reports;
  Bus bus("memq://", key_of('a'), [&reports](const std::string& line) { reports.push_back(line); });
  int calls = 0;
  bus.subscribe("TL_BAD", [&calls](const BusMessage&) {
    ++calls;
    throw std::length_error("vector::_M_default_append");
  });
  Received got;
  listen(bus, "TL_GOOD", got);
  bus.publish("TL_BAD", pose(1));
  bus.publish("TL_GOOD", pose(2));
  bus.publish("TL_BAD", pose(3));
  bus.drain();
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(bus.counters().handler_failures, 2);
  EXPECT_EQ(got.x_mm, std::vector<float>{2});
  ASSERT_FALSE(reports.empty());
  EXPECT_NE(reports[0].find("TL_BAD: handler failed: vector::_M_default_append"), std::string::npos) << reports[0];
}

TEST(Bus, AnUnusableUrlIsOneLine) {
  try {
    Bus bus("nosuchprovider://", key_of('a'));
    FAIL() << "opened";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open LCM at nosuchprovider://"), std::string::npos) << e.what();
  }
}

TEST(Bus, OnAUrlOfOneLaneTheRobotsAnswersAndTheWorldsMessagesShareIt) {
  // memq:// (as in every in-process test) has no port above it: both lanes are the one bus.
  Bus bus("memq://", key_of('a'));
  EXPECT_FALSE(bus.urls().split());
  Received answers, senses;
  listen(bus, "TL_ACT_.*", answers);
  listen(bus, "TL_SENSE", senses);
  bus.publish("TL_ACT_0_1", pose(1));
  bus.publish("TL_SENSE", pose(2));
  bus.drain();
  EXPECT_EQ(answers.x_mm, std::vector<float>{1});
  EXPECT_EQ(senses.x_mm, std::vector<float>{2});
}
