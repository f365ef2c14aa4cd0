#include "tendril/rl/schedule.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"
#include "tendril/rl/minibatches.hpp"

namespace tendril::rl {
namespace {

TEST(Schedule, ConstantAndLinearToZero) {
  const Schedule constant{3e-4, false};
  EXPECT_DOUBLE_EQ(constant.at(1.0), 3e-4);
  EXPECT_DOUBLE_EQ(constant.at(0.1), 3e-4);
  const Schedule linear{1e-3, true};
  EXPECT_DOUBLE_EQ(linear.at(1.0), 1e-3);
  EXPECT_DOUBLE_EQ(linear.at(0.25), 2.5e-4);
  EXPECT_DOUBLE_EQ(linear.at(0.0), 0.0);
}

TEST(Schedule, ReadFromConfig) {
  const Config config = Config::parse("learning_rate: 1e-3\nlearning_rate_schedule: linear\n");
  const Schedule read = read_schedule(config, "learning_rate", {3e-4, false});
  EXPECT_DOUBLE_EQ(read.initial, 1e-3);
  EXPECT_TRUE(read.linear);
  EXPECT_FALSE(read_schedule(Config::parse("{}"), "clip_range", {0.2, false}).linear);
  EXPECT_THROW(
      read_schedule(Config::parse("clip_range_schedule: cosine\n"), "clip_range", {0.2, false}),
      Error);
}

TEST(Minibatches, PermutationCutIntoBatchesWithRemainder) {
  Rng rng(3);
  const auto batches = shuffled_minibatches(10, 4, rng);
  ASSERT_EQ(batches.size(), 3u);
  EXPECT_EQ(batches[0].size(0), 4);
  EXPECT_EQ(batches[2].size(0), 2);
  std::vector<int64_t> seen;
  for (const auto& batch : batches) {
    for (int64_t i = 0; i < batch.size(0); ++i) seen.push_back(batch[i].item<int64_t>());
  }
  std::sort(seen.begin(), seen.end());
  for (int64_t i = 0; i < 10; ++i) EXPECT_EQ(seen[i], i);
  Rng same(3);
  EXPECT_TRUE(torch::equal(shuffled_minibatches(10, 4, same)[0], batches[0]));
}

}  // namespace
}  // namespace tendril::rl
