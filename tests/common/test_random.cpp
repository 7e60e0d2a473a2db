// Keyed draws: each a pure function of its key, the same on every platform, and
// uncorrelated between neighbouring keys.
#include "touchline/random.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include <gtest/gtest.h>

using namespace touchline;

namespace {

uint64_t first(uint64_t seed, DrawStream stream, int64_t when, uint64_t who, uint32_t what) {
  auto draws = keyed_draws(seed, stream, when, who, what);
  return draws();
}

/// A generator of one fixed value, to pin uniform01's arithmetic.
struct Constant {
  using result_type = uint64_t;
  uint64_t value;
  uint64_t operator()() const { return value; }
};

} // namespace

TEST(KeyedDraws, AreThreefry4x64OfTheKeyAndTheFrame) {
  // Random123's published known answer for Threefry4x64-20, key and counter all zero:
  // the same numbers whatever the compiler or machine (MicroURNG hands out the block's
  // words last first).
  auto draws = keyed_draws(0, DrawStream{0}, 0, 0, 0);
  EXPECT_EQ(draws(), 0xee29ec846bd2e40bull);
  EXPECT_EQ(draws(), 0x4bd25e16282434dcull);
  EXPECT_EQ(draws(), 0x55941f5266d86105ull);
  EXPECT_EQ(draws(), 0x09218ebde6c85537ull);
  EXPECT_NE(draws(), 0xee29ec846bd2e40bull); // the next block
}

TEST(KeyedDraws, TheSameKeyGivesTheSameDrawsInAnyOrder) {
  auto a = keyed_draws(9, DrawStream::kTeamMessage, 300, draw_id(0, 1), draw_id(0, 2));
  const uint64_t a1 = a(), a2 = a();
  (void)first(9, DrawStream::kTeamMessage, 301, draw_id(0, 1), draw_id(0, 2)); // another key between
  auto b = keyed_draws(9, DrawStream::kTeamMessage, 300, draw_id(0, 1), draw_id(0, 2));
  EXPECT_EQ(b(), a1);
  EXPECT_EQ(b(), a2);
  EXPECT_NE(a1, a2);
}

TEST(KeyedDraws, EveryPartOfTheKeyMatters) {
  const uint64_t base = first(9, DrawStream::kCamera, 300, draw_id(0, 1), 5);
  std::set<uint64_t> seen = {base,
                             first(10, DrawStream::kCamera, 300, draw_id(0, 1), 5),
                             first(9, DrawStream::kSonar, 300, draw_id(0, 1), 5),
                             first(9, DrawStream::kCamera, 301, draw_id(0, 1), 5),
                             first(9, DrawStream::kCamera, 300, draw_id(1, 1), 5),
                             first(9, DrawStream::kCamera, 300, draw_id(0, 2), 5),
                             first(9, DrawStream::kCamera, 300, draw_id(0, 1), 6)};
  EXPECT_EQ(seen.size(), 7u);
}

TEST(KeyedDraws, RobotIdsAreDistinct) {
  std::set<uint32_t> ids;
  for (int team = 0; team < 2; ++team)
    for (int player = 1; player <= 7; ++player) ids.insert(draw_id(team, player));
  EXPECT_EQ(ids.size(), 14u);
}

TEST(KeyedDraws, NeighbouringFramesGiveIndependentUniforms) {
  // The first draw of 20000 consecutive frames: mean 1/2, variance 1/12, and no
  // correlation between one frame and the next (each within 4 standard errors).
  const int n = 20000;
  double sum = 0, sum_sq = 0, sum_lag = 0, previous = 0;
  for (int f = 0; f < n; ++f) {
    auto draws = keyed_draws(3, DrawStream::kFall, f, draw_id(1, 4));
    const double u = uniform01(draws);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u, sum_sq += u * u;
    if (f > 0) sum_lag += (u - 0.5) * (previous - 0.5);
    previous = u;
  }
  const double mean = sum / n, variance = sum_sq / n - mean * mean, lag_correlation = sum_lag / (n - 1) * 12;
  EXPECT_NEAR(mean, 0.5, 4 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(variance, 1.0 / 12, 0.003);
  EXPECT_NEAR(lag_correlation, 0, 4 / std::sqrt(n));
}

TEST(Uniform01, IsTheTop53BitsOfOneDraw) {
  Constant max{std::numeric_limits<uint64_t>::max()}, low{(uint64_t{1} << 11) - 1}, half{uint64_t{1} << 63};
  EXPECT_EQ(uniform01(max), 1.0 - 0x1.0p-53); // never 1
  EXPECT_EQ(uniform01(low), 0.0);             // the low 11 bits are dropped
  EXPECT_EQ(uniform01(half), 0.5);
}
