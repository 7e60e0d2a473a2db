// Bounded fuzzing of the GameController packet decoder (sim/src/gamecontroller.cpp), with
// and without configured team numbers: every input decodes into a consistent packet or is a
// GameControllerError, nothing else (checks.hpp). Same mutations as the LCM types.
#include <vector>

#include <gtest/gtest.h>

#include "checks.hpp"
#include "samples.hpp"

using namespace touchline;
using fuzz::Bytes;

namespace {

struct Outcomes {
  int decoded = 0;
  int rejected = 0;
};

bool check(const Bytes& bytes, const sim::GameControllerConfig& config, Outcomes& outcomes) {
  const fuzz::Verdict verdict = fuzz::check_gamecontroller(bytes, config);
  if (!verdict.failure.empty()) {
    ADD_FAILURE() << verdict.failure;
    return false;
  }
  ++(verdict.decoded ? outcomes.decoded : outcomes.rejected);
  return true;
}

} // namespace

TEST(FuzzGameController, EveryInputDecodesOrIsAGameControllerError) {
  const std::vector<Bytes> seeds = fuzz::gamecontroller_samples();
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
