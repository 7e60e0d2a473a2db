// Bounded fuzzing of every LCM type (all_lcm_types.hpp lists lcm_types/*.lcm) through every
// decoder on the receiving side (checks.hpp says what each input must satisfy). The
// inputs: every 1-, 2-, 4- and 8-byte window of valid encodings set to edge values, then
// seeded random mutants (mutator.hpp). The sanitizer build runs this test too.
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "checks.hpp"
#include "samples.hpp"
#include "touchline/hash.hpp"

using namespace touchline;
using fuzz::Bytes;

namespace {

struct Outcomes {
  int decoded = 0;
  int malformed = 0;
};

/// Adds a test failure and returns false if `bytes` breaks a rule of checks.hpp.
template <typename Msg>
bool check(const Bytes& bytes, Outcomes& outcomes) {
  const fuzz::Verdict verdict = fuzz::check_lcm<Msg>(bytes);
  if (!verdict.failure.empty()) {
    ADD_FAILURE() << verdict.failure;
    return false;
  }
  ++(verdict.decoded ? outcomes.decoded : outcomes.malformed);
  return true;
}

template <typename Msg>
class FuzzLcm : public ::testing::Test {};

struct TypeName {
  template <typename Msg>
  static std::string GetName(int) {
    return Msg::getTypeName();
  }
};

TYPED_TEST_SUITE(FuzzLcm, ::testing::Types<TOUCHLINE_ALL_LCM_TYPES>, TypeName);

} // namespace

TYPED_TEST(FuzzLcm, EveryInputDecodesOrIsMalformed) {
  using Msg = TypeParam;
  const std::vector<Bytes> seeds = fuzz::sample_encodings<Msg>();
  Outcomes samples_outcome;
  for (const Bytes& seed : seeds) ASSERT_TRUE(check<Msg>(seed, samples_outcome));
  ASSERT_EQ(samples_outcome.malformed, 0) << "a sample of " << Msg::getTypeName() << " is itself malformed";

  Outcomes outcomes;
  bool ok = true;
  fuzz::sweep_edge_values(seeds, [&](const Bytes& bytes) { ok = ok && check<Msg>(bytes, outcomes); });
  ASSERT_TRUE(ok);

  Fnv1a type_hash;
  type_hash.add(Msg::getTypeName(), std::char_traits<char>::length(Msg::getTypeName()));
  fuzz::Mutator mutator(fuzz::seed() ^ type_hash.value(), seeds, /*keep: the fingerprint*/ 8);
  const int n = fuzz::iterations();
  for (int i = 0; i < n && check<Msg>(mutator.next(), outcomes); ++i) {
  }
  // Both outcomes, or the inputs never reached past the fingerprint check (or never failed).
  EXPECT_GT(outcomes.decoded, 0);
  EXPECT_GT(outcomes.malformed, 0);
  std::cout << Msg::getTypeName() << ": " << outcomes.decoded << " decoded, " << outcomes.malformed
            << " malformed\n";
}
