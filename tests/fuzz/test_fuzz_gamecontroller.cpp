// Bounded fuzzing of the GameController packet decoder (sim/src/gamecontroller.cpp), with
// and without configured team numbers: every input decodes into a consistent packet or is a
// GameControllerError, nothing else. Same mutations as the LCM types (mutator.hpp).
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mutator.hpp"
#include "touchline/sim/gamecontroller.hpp"

using namespace touchline;
using fuzz::Bytes;
namespace gc = sim::gamecontroller;

namespace {

/// A valid data packet (layout in gamecontroller.hpp): teams 5 and 12, one penalty each.
Bytes packet(int version, int state, int kicking_team) {
  Bytes b(gc::kPacketSize, 0);
  for (size_t i = 0; i < 4; ++i) b[i] = static_cast<uint8_t>(gc::kHeader[i]);
  b[4] = static_cast<uint8_t>(version);
  b[6] = 5;   // playersPerTeam
  b[10] = static_cast<uint8_t>(state);
  b[12] = 1;  // firstHalf
  b[13] = static_cast<uint8_t>(kicking_team);
  b[14] = 0x58, b[15] = 0x02; // secsRemaining 600, little-endian
  const size_t teams_at = 18, team_size = 10 + 2 * gc::kMaxNumPlayers;
  b[teams_at] = 5;
  b[teams_at + team_size] = 12;
  b[teams_at + 4] = 2;                       // team 5 scored twice
  b[teams_at + 10 + 2] = 1;                  // team 5's player 2: penalised ...
  b[teams_at + 10 + 3] = 30;                 // ... for 30 s
  b[teams_at + team_size + 10 + 12] = 14;    // team 12's player 7: substitute
  return b;
}

struct Outcomes {
  int decoded = 0;
  int rejected = 0;
};

bool check(const Bytes& bytes, const sim::GameControllerConfig& config, Outcomes& outcomes) {
  sim::GameControllerPacket p;
  try {
    p = sim::decode_gamecontroller_packet(bytes.data(), bytes.size(), config);
  } catch (const sim::GameControllerError&) {
    ++outcomes.rejected;
    return true;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "\"" << e.what() << "\" is not a GameControllerError, on " << fuzz::hex(bytes);
    return false;
  }
  ++outcomes.decoded;
  const auto state = static_cast<int>(p.game.state);
  const bool consistent = state >= 0 && state <= static_cast<int>(GameState::kFinished) &&
                          (!p.standby || p.version == 18) &&
                          (p.game.kickoff_team == 0 || p.game.kickoff_team == 1) &&
                          (!p.kicking_team || *p.kicking_team == p.game.kickoff_team) &&
                          p.team_numbers[0] != p.team_numbers[1] &&
                          std::set<int>{p.packet_slot[0], p.packet_slot[1]} == std::set<int>{0, 1};
  if (!consistent) ADD_FAILURE() << "decoded into an inconsistent packet: " << fuzz::hex(bytes);
  return consistent;
}

} // namespace

TEST(FuzzGameController, EveryInputDecodesOrIsAGameControllerError) {
  const std::vector<Bytes> seeds = {packet(15, 3, 5), packet(18, 5, gc::kKickingTeamNone), packet(18, 1, 12)};
  sim::GameControllerConfig by_number;
  by_number.team_numbers = {{12, 5}};
  for (const sim::GameControllerConfig& config : {sim::GameControllerConfig{}, by_number}) {
    Outcomes seeds_outcome;
    for (const Bytes& seed : seeds) ASSERT_TRUE(check(seed, config, seeds_outcome));
    ASSERT_EQ(seeds_outcome.rejected, 0) << "a seed packet is itself rejected";

    Outcomes outcomes;
    bool ok = true;
    fuzz::sweep_edge_values(seeds, [&](const Bytes& bytes) { ok = ok && check(bytes, config, outcomes); });
    ASSERT_TRUE(ok);
    fuzz::Mutator mutator(fuzz::seed(), seeds, /*keep: header and version*/ 5);
    const int n = fuzz::iterations();
    for (int i = 0; i < n && check(mutator.next(), config, outcomes); ++i) {
    }
    EXPECT_GT(outcomes.decoded, 0);
    EXPECT_GT(outcomes.rejected, 0);
  }
}
