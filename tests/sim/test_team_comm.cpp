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
