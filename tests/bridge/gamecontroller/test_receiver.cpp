// The GameController receiver on loopback only: it binds 127.0.0.1 on an ephemeral port
// and this test sends it datagrams from a second socket.
#include "touchline/gamecontroller/receiver.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

using namespace touchline;
using transport::GameControllerReceiver;
using transport::GameControllerReceiverOptions;

namespace {

// A version-15 packet per the documented layout (see touchline/gamecontroller/packet.hpp):
// teams 5 and 12, team 5 kicking off.
std::vector<uint8_t> packet(uint8_t packet_number, uint8_t state, uint8_t score0, uint8_t score1) {
  std::vector<uint8_t> b(118, 0);
  b[0] = 'R', b[1] = 'G', b[2] = 'm', b[3] = 'e';
  b[4] = 15;
  b[5] = packet_number;
  b[6] = 5;    // playersPerTeam
  b[10] = state;
  b[12] = 1;   // firstHalf
  b[13] = 5;   // kickingTeam
  b[14] = 0x58, b[15] = 0x02; // secsRemaining 600
  b[18] = 5;   // teams[0].teamNumber
  b[22] = score0;
  b[68] = 12;  // teams[1].teamNumber
  b[72] = score1;
  b[68 + 10 + 2 * 3] = 2;      // teams[1].players[3].penalty: pushing
  b[68 + 10 + 2 * 3 + 1] = 20; // ... 20 s left
  return b;
}

class Sender {
 public:
  explicit Sender(uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd_ < 0) throw std::runtime_error("socket failed");
    to_.sin_family = AF_INET;
    to_.sin_port = htons(port);
    to_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  }
  ~Sender() { ::close(fd_); }
  Sender(const Sender&) = delete;
  Sender& operator=(const Sender&) = delete;
  void send(const std::vector<uint8_t>& bytes) {
    const ssize_t n = ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to_),
                               sizeof to_);
    ASSERT_EQ(n, static_cast<ssize_t>(bytes.size()));
  }

 private:
  int fd_ = -1;
  sockaddr_in to_{};
};

GameControllerReceiverOptions ephemeral() {
  GameControllerReceiverOptions o;
  o.address = "127.0.0.1";
  o.port = 0;
  return o;
}

// Polls until `datagrams` have been read (good + bad), for at most 2 s; the latest
// valid packet any poll returned.
std::optional<sim::GameControllerPacket> poll_until(GameControllerReceiver& rx, int64_t datagrams) {
  std::optional<sim::GameControllerPacket> latest;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (rx.good_packets() + rx.bad_packets() < datagrams && std::chrono::steady_clock::now() < deadline) {
    if (auto p = rx.poll()) latest = std::move(p);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (auto p = rx.poll()) latest = std::move(p);
  return latest;
}

} // namespace

TEST(GameControllerReceiver, DefaultsToLoopbackAndTheGameControllerPort) {
  const GameControllerReceiverOptions o;
  EXPECT_EQ(o.address, "127.0.0.1");
  EXPECT_EQ(o.port, 3838);
}

TEST(GameControllerReceiver, BindsAnEphemeralPort) {
  GameControllerReceiver rx(ephemeral());
  EXPECT_NE(rx.port(), 0);
  EXPECT_EQ(rx.address(), "127.0.0.1");
}

TEST(GameControllerReceiver, PollWithNothingPendingReturnsAtOnce) {
  GameControllerReceiver rx(ephemeral());
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(rx.poll().has_value());
  const auto elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_LT(elapsed, std::chrono::milliseconds(100));
  EXPECT_EQ(rx.good_packets(), 0);
  EXPECT_EQ(rx.bad_packets(), 0);
}

TEST(GameControllerReceiver, ReturnsTheLatestValidPacketAndCountsBadOnes) {
  GameControllerReceiver rx(ephemeral());
  Sender tx(rx.port());
  tx.send(packet(1, 1, 0, 0));                 // READY
  tx.send(packet(2, 3, 1, 0));                 // PLAYING, 1:0
  tx.send({'g', 'a', 'r', 'b', 'a', 'g', 'e'}); // not a packet
  const auto p = poll_until(rx, 3);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->packet_number, 2);
  EXPECT_EQ(p->game.state, GameState::kPlaying);
  EXPECT_EQ(p->game.score, (std::array<int, 2>{{1, 0}}));
  EXPECT_EQ(p->game.secs_remaining, 600);
  EXPECT_EQ(p->game.kickoff_team, 0);
  EXPECT_TRUE(p->penalties[1][3].penalised);
  EXPECT_EQ(p->penalties[1][3].secs_till_unpenalised, 20);
  EXPECT_EQ(rx.good_packets(), 2);
  EXPECT_EQ(rx.bad_packets(), 1);
  EXPECT_EQ(rx.last_error(), "GameController packet: header \"garb\", expected \"RGme\"");

  // Everything was read: the next poll has nothing.
  EXPECT_FALSE(rx.poll().has_value());
}

TEST(GameControllerReceiver, BadPacketsBetweenGoodOnesAreSkipped) {
  GameControllerReceiver rx(ephemeral());
  Sender tx(rx.port());
  std::vector<uint8_t> wrong_version = packet(9, 3, 0, 0);
  wrong_version[4] = 12;
  std::vector<uint8_t> too_long = packet(10, 3, 0, 0);
  too_long.resize(2000, 0);
  tx.send(packet(7, 2, 0, 0));
  tx.send(wrong_version);
  tx.send(too_long);
  tx.send(packet(8, 4, 2, 3));
  tx.send({});
  const auto p = poll_until(rx, 5);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->packet_number, 8);
  EXPECT_EQ(p->game.state, GameState::kFinished);
  EXPECT_EQ(rx.good_packets(), 2);
  EXPECT_EQ(rx.bad_packets(), 3);
}

TEST(GameControllerReceiver, MapsTeamsByConfiguredNumbers) {
  GameControllerReceiverOptions o = ephemeral();
  o.decode.team_numbers = std::array<int, 2>{{12, 5}};
  GameControllerReceiver rx(o);
  Sender tx(rx.port());
  tx.send(packet(1, 3, 2, 1)); // team 5: 2, team 12: 1
  const auto p = poll_until(rx, 1);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->game.score, (std::array<int, 2>{{1, 2}}));
  EXPECT_EQ(p->game.kickoff_team, 1);
  EXPECT_TRUE(p->penalties[0][3].penalised);

  // A packet from a game between other teams is bad.
  std::vector<uint8_t> others = packet(2, 3, 0, 0);
  others[18] = 40;
  others[13] = 40;
  tx.send(others);
  EXPECT_FALSE(poll_until(rx, 2).has_value());
  EXPECT_EQ(rx.bad_packets(), 1);
  EXPECT_EQ(rx.last_error(), "GameController packet: teams 40 and 12, expected 12 and 5");
}

TEST(GameControllerReceiver, BadAddressOrBusyPortThrows) {
  GameControllerReceiverOptions o = ephemeral();
  o.address = "localhost";
  EXPECT_THROW(GameControllerReceiver{o}, std::invalid_argument);
  o.address = "127.0.0.1";
  o.decode.team_numbers = std::array<int, 2>{{3, 3}};
  EXPECT_THROW(GameControllerReceiver{o}, std::invalid_argument);

  GameControllerReceiver first(ephemeral());
  GameControllerReceiverOptions same = ephemeral();
  same.port = first.port();
  try {
    GameControllerReceiver second(same);
    FAIL() << "bound a port already bound";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot bind 127.0.0.1:" + std::to_string(first.port())),
              std::string::npos)
        << e.what();
  }
}
