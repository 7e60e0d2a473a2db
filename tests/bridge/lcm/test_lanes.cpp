// lanes: which channel travels on which lane, and the URL of each lane derived from the one
// --lcm-url (no network: only strings).
#include "touchline/lcm/lanes.hpp"

#include <gtest/gtest.h>

#include "touchline/lcm/codec.hpp"

namespace touchline::transport {
namespace {

TEST(Lanes, WhatRobotsSendTheWorldIsOnTheUplinkAndEverythingElseOnTheMatchUrl) {
  // (what the robots need is copied to the robots' lane: to_robots below)
  for (const char* uplink : {"TL_ACT_0_1", "TL_ACT_1_5", "TL_JOIN", "TL_BLACKBOARD_1_2", kActChannelPattern,
                             kSnapshotChannelPattern, kJoinChannel})
    EXPECT_EQ(lane_of(uplink), Lane::kUplink) << uplink;
  for (const char* match : {kSenseChannel, kTruthChannel, kGameChannel, kStatusChannel, kEventChannel,
                            kJoinReplyChannel, "TL_MATCH", ".*", "TL_JOINED", "OTHER"})
    EXPECT_EQ(lane_of(match), Lane::kMatch) << match;
}

TEST(Lanes, TheRobotsHearTheSenseTheGameAndTheAnswerToTheirJoinOnly) {
  for (const char* copied : {kSenseChannel, kGameChannel, kJoinReplyChannel}) EXPECT_TRUE(to_robots(copied)) << copied;
  for (const char* not_copied : {kTruthChannel, kStatusChannel, kEventChannel, "TL_MATCH", "TL_ACT_0_1", kJoinChannel,
                                 "TL_SENSE_X", ".*"})
    EXPECT_FALSE(to_robots(not_copied)) << not_copied;
}

TEST(Lanes, AUdpmUrlsUplinkAndRobotsLanesAreTheTwoPortsAboveWithTheSameGroupAndOptions) {
  struct Case {
    const char* url;
    const char* uplink;
    const char* robots;
  };
  for (const Case& c : {
           Case{"udpm://239.255.76.67:7667?ttl=0", "udpm://239.255.76.67:7668?ttl=0", "udpm://239.255.76.67:7669?ttl=0"},
           Case{"udpm://239.255.76.67:7667?ttl=1&recv_buf_size=2097152",
                "udpm://239.255.76.67:7668?ttl=1&recv_buf_size=2097152",
                "udpm://239.255.76.67:7669?ttl=1&recv_buf_size=2097152"},
           Case{"udpm://239.1.2.3:9000", "udpm://239.1.2.3:9001", "udpm://239.1.2.3:9002"},
           Case{"udpm://", "udpm://239.255.76.67:7668", "udpm://239.255.76.67:7669"}, // LCM's default group and port
           Case{"udpm://?ttl=0", "udpm://239.255.76.67:7668?ttl=0", "udpm://239.255.76.67:7669?ttl=0"},
           // LCM reads the port as strtol(.., 0) does
           Case{"udpm://239.1.2.3:0x1000", "udpm://239.1.2.3:4097", "udpm://239.1.2.3:4098"},
           Case{"udpm://239.1.2.3:65533", "udpm://239.1.2.3:65534", "udpm://239.1.2.3:65535"},
       }) {
    const LaneUrls urls = lane_urls(c.url);
    EXPECT_EQ(urls.match, c.url);
    EXPECT_EQ(urls.uplink, c.uplink) << c.url;
    EXPECT_EQ(urls.robots, c.robots) << c.url;
    EXPECT_TRUE(urls.split());
    EXPECT_EQ(urls.of(Lane::kUplink), c.uplink);
    EXPECT_EQ(urls.of(Lane::kRobots), c.robots);
    EXPECT_EQ(urls.of(Lane::kMatch), c.url);
  }
}

TEST(Lanes, OtherUrlsAndUdpmUrlsWithNoPortAboveCarryBothLanesOnOneUrl) {
  // lcm_url_problem() refuses the udpm ones among these with a reason.
  for (const char* url : {"memq://", "tcpq://127.0.0.1:7700", "file:///tmp/x.lcmlog", "udpm://239.1.2.3:65534",
                          "udpm://239.1.2.3:65535", "udpm://239.1.2.3:99999", "udpm://239.1.2.3:x", "udpm://239.1.2.3", ""}) {
    const LaneUrls urls = lane_urls(url);
    EXPECT_FALSE(urls.split()) << url;
    EXPECT_EQ(urls.uplink, url);
    EXPECT_EQ(urls.robots, url);
  }
}

} // namespace
} // namespace touchline::transport
