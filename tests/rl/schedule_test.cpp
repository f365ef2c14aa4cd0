#include "tendril/rl/schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "tendril/core/error.hpp"
#include "tendril/rl/rollout_minibatches.hpp"

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

TEST(Schedule, LinearToAFloor) {
  Schedule actor{3e-3, true};
  actor.final = 1e-4;
  EXPECT_DOUBLE_EQ(actor.at(1.0), 3e-3);
  EXPECT_DOUBLE_EQ(actor.at(0.5), 1.55e-3);
  EXPECT_DOUBLE_EQ(actor.at(0.0), 1e-4);
  const Config config = Config::parse(
      "learning_rate: 3e-3\nlearning_rate_schedule: linear\nlearning_rate_final: 1e-4\n");
  const Schedule read = read_schedule(config, "learning_rate", {3e-4, false});
  EXPECT_DOUBLE_EQ(read.at(0.0), 1e-4);
  EXPECT_THROW(
      read_schedule(Config::parse("learning_rate_final: 1e-4\n"), "learning_rate", {3e-4, false}),
      Error);
  EXPECT_THROW(read_schedule(Config::parse("learning_rate_schedule: linear\n"
                                           "learning_rate_final: -1\n"),
                             "learning_rate", {3e-4, false}),
               Error);
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

TEST(RandomPermutation, IsAPermutationDrawnFromTheStream) {
  Rng rng(3);
  std::vector<int64_t> order = random_permutation(10, rng);
  Rng same(3);
  EXPECT_EQ(random_permutation(10, same), order);
  Rng other(4);
  EXPECT_NE(random_permutation(10, other), order);
  std::sort(order.begin(), order.end());
  for (int64_t i = 0; i < 10; ++i) EXPECT_EQ(order[i], i);
}

}  // namespace
}  // namespace tendril::rl
