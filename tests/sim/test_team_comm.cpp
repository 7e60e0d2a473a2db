#include "touchline/sim/team_comm.hpp"

#include <cmath>

#include <gtest/gtest.h>

using namespace touchline;
using sim::CommDef;
using sim::SendResult;
using sim::TeamComm;

namespace {

const std::vector<RobotId> kField = {{0, 1}, {0, 2}, {0, 3}, {1, 1}, {1, 2}};
const std::vector<uint8_t> kHello = {'h', 'i'};

CommDef lossless() {
  CommDef def;
  def.loss_probability = 0;
  return def;
}

} // namespace

TEST(TeamComm, ArrivesAtEveryTeammateAfterTheLatencyAndOnlyOnce) {
  TeamComm comm(lossless(), 1);
  EXPECT_EQ(comm.send({0, 1}, 1000000, kHello, kField), SendResult::kSent);
  EXPECT_TRUE(comm.receive({0, 2}, 1099999).empty()); // latency 100 ms
  const auto arrived = comm.receive({0, 2}, 1100000);
  ASSERT_EQ(arrived.size(), 1u);
  EXPECT_EQ(arrived[0].player, 1);
  EXPECT_EQ(arrived[0].sent_utime, 1000000);
  EXPECT_EQ(arrived[0].data, kHello);
  EXPECT_TRUE(comm.receive({0, 2}, 2000000).empty()); // handed out once
  EXPECT_EQ(comm.receive({0, 3}, 2000000).size(), 1u);
  EXPECT_TRUE(comm.receive({0, 1}, 2000000).empty()); // not to itself
  EXPECT_TRUE(comm.receive({1, 1}, 2000000).empty()); // nor to the opponents
}

TEST(TeamComm, RefusesMessagesTooLongOrTooSoon) {
  TeamComm comm(lossless(), 1);
  EXPECT_EQ(comm.send({0, 1}, 0, std::vector<uint8_t>(129, 0), kField), SendResult::kTooLong);
  EXPECT_EQ(comm.send({0, 1}, 0, std::vector<uint8_t>(128, 0), kField), SendResult::kSent);
  EXPECT_EQ(comm.send({0, 1}, 199999, kHello, kField), SendResult::kTooSoon); // 5 Hz: 200 ms apart
  EXPECT_EQ(comm.send({0, 2}, 199999, kHello, kField), SendResult::kSent);    // each robot its own budget
  EXPECT_EQ(comm.send({0, 1}, 200000, kHello, kField), SendResult::kSent);
  EXPECT_EQ(comm.refused(), 2);
}

TEST(TeamComm, LossRateMatchesTheConfiguredProbability) {
  CommDef def;
  def.loss_probability = 0.2f;
  TeamComm comm(def, 42);
  const std::vector<RobotId> team = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}, {0, 6}, {0, 7}};
  const int sends = 2000;
  for (int i = 0; i < sends; ++i) comm.send({0, 1}, int64_t{i} * 200000, kHello, team);
  int received = 0;
  for (const RobotId& id : team) received += static_cast<int>(comm.receive(id, int64_t{sends} * 200000 + 1000000).size());
  const double trials = sends * 6.0, p = 0.2;
  const double lost_fraction = 1.0 - received / trials;
  EXPECT_NEAR(lost_fraction, p, 3 * std::sqrt(p * (1 - p) / trials)); // within 3 sigma
  EXPECT_EQ(comm.lost() + comm.delivered(), static_cast<int64_t>(trials));
}

TEST(TeamComm, SameSeedSameLosses) {
  CommDef def;
  def.loss_probability = 0.5f;
  TeamComm a(def, 3), b(def, 3), c(def, 4);
  for (int i = 0; i < 200; ++i) {
    a.send({0, 1}, int64_t{i} * 200000, kHello, kField);
    b.send({0, 1}, int64_t{i} * 200000, kHello, kField);
    c.send({0, 1}, int64_t{i} * 200000, kHello, kField);
  }
  EXPECT_EQ(a.lost(), b.lost());
  EXPECT_NE(a.lost(), c.lost());
}

TEST(TeamComm, LossesAndDeliveriesDoNotDependOnTheOrderOfSending) {
  // Three teammates send in the same frames, handed in in opposite orders: each delivery is
  // lost or not by its own keyed draw, and what arrives together comes in sender order.
  CommDef def;
  def.loss_probability = 0.3f;
  TeamComm forwards(def, 9), backwards(def, 9);
  const std::vector<RobotId> senders = {{0, 1}, {0, 2}, {0, 3}};
  for (int i = 0; i < 50; ++i) {
    const int64_t utime = int64_t{i} * 200000;
    for (auto it = senders.begin(); it != senders.end(); ++it)
      forwards.send(*it, utime, {static_cast<uint8_t>(it->player), static_cast<uint8_t>(i)}, kField);
    for (auto it = senders.rbegin(); it != senders.rend(); ++it)
      backwards.send(*it, utime, {static_cast<uint8_t>(it->player), static_cast<uint8_t>(i)}, kField);
  }
  EXPECT_EQ(forwards.lost(), backwards.lost());
  EXPECT_GT(forwards.lost(), 0);
  for (const RobotId& to : senders) {
    for (int64_t utime = 0; utime <= 11000000; utime += 100000) {
      const auto a = forwards.receive(to, utime), b = backwards.receive(to, utime);
      ASSERT_EQ(a.size(), b.size());
      for (size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].player, b[k].player);
        EXPECT_EQ(a[k].data, b[k].data);
        if (k > 0 && a[k].sent_utime == a[k - 1].sent_utime) {
          EXPECT_LT(a[k - 1].player, a[k].player);
        }
      }
    }
  }
  EXPECT_EQ(forwards.delivered(), backwards.delivered());
}

TEST(TeamComm, OneRobotsMessagesDoNotShiftAnothersLosses) {
  // Robot 2 talking or not leaves the fate of robot 1's messages as it was.
  CommDef def;
  def.loss_probability = 0.5f;
  TeamComm quiet(def, 11), chatty(def, 11);
  for (int i = 0; i < 100; ++i) {
    const int64_t utime = int64_t{i} * 200000;
    chatty.send({0, 2}, utime, kHello, kField);
    quiet.send({0, 1}, utime, kHello, kField);
    chatty.send({0, 1}, utime, kHello, kField);
  }
  for (const RobotId& to : {RobotId{0, 2}, RobotId{0, 3}}) {
    std::vector<int64_t> heard_quiet, heard_chatty;
    for (const auto& m : quiet.receive(to, 30000000)) heard_quiet.push_back(m.sent_utime);
    for (const auto& m : chatty.receive(to, 30000000))
      if (m.player == 1) heard_chatty.push_back(m.sent_utime);
    EXPECT_EQ(heard_quiet, heard_chatty);
    EXPECT_GT(heard_quiet.size(), 20u);
    EXPECT_LT(heard_quiet.size(), 80u);
  }
}
