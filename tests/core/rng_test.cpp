#include "tendril/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace tendril {
namespace {

TEST(Rng, SameSeedAndStreamGiveSameSequence) {
  Rng a(42, 3), b(42, 3);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_u64(), b.next_u64());
}

TEST(Rng, StreamsAndSeedsDiffer) {
  std::set<uint64_t> first_values;
  for (uint64_t seed = 0; seed < 4; ++seed) {
    for (uint64_t stream = 0; stream < 4; ++stream)
      first_values.insert(Rng(seed, stream).next_u64());
  }
  EXPECT_EQ(first_values.size(), 16u);
  Rng base(7);
  EXPECT_NE(base.derive(1).next_u64(), base.derive(2).next_u64());
  EXPECT_EQ(base.derive(1).next_u64(), Rng(7).derive(1).next_u64());
}

TEST(Rng, UniformAndNormalMoments) {
  Rng rng(1);
  const int n = 200000;
  double sum = 0, sum_sq = 0, normal_sum = 0, normal_sq = 0;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum_sq += u * u;
    const double z = rng.normal();
    normal_sum += z;
    normal_sq += z * z;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);
  EXPECT_NEAR(sum_sq / n - 0.25, 1.0 / 12.0, 0.002);
  EXPECT_NEAR(normal_sum / n, 0.0, 0.01);
  EXPECT_NEAR(normal_sq / n, 1.0, 0.01);
}

TEST(Rng, BelowIsUnbiasedAndInRange) {
  Rng rng(5);
  std::array<int, 3> counts{};
  for (int i = 0; i < 30000; ++i) {
    const uint64_t k = rng.below(3);
    ASSERT_LT(k, 3u);
    counts[k]++;
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 400);
}

// With n = 3 · 2⁶², a plain `next_u64() % n` would put [0, 2⁶²) twice as often as the rest (half
// of the draws instead of a third); rejection sampling keeps it uniform. Here the rejection
// threshold is n itself, so each result is the first raw draw below n.
TEST(Rng, BelowRejectsTheBiasedTailForLargeRanges) {
  const uint64_t n = 3ull << 62;
  Rng rng(6), raw(6);
  int low = 0;
  const int draws = 4000;
  for (int i = 0; i < draws; ++i) {
    const uint64_t k = rng.below(n);
    ASSERT_LT(k, n);
    uint64_t x;
    do {
      x = raw.next_u64();
    } while (x >= n);
    ASSERT_EQ(k, x) << "draw " << i;
    low += k < (1ull << 62);
  }
  // A third below 2⁶² (standard error 0.0075); the modulo bias would give a half.
  EXPECT_NEAR(static_cast<double>(low) / draws, 1.0 / 3.0, 0.04);
}

TEST(Rng, StateRoundTripRestoresSequence) {
  Rng rng(9);
  rng.normal();  // leaves a spare normal in the state
  const Rng::State saved = rng.state();
  const double a = rng.normal(), b = rng.uniform();
  Rng other(123);
  other.set_state(saved);
  EXPECT_EQ(other.normal(), a);
  EXPECT_EQ(other.uniform(), b);
}

}  // namespace
}  // namespace tendril
