// The minibatches of a rollout (SB3's RolloutBuffer.get) that PPO and TRPO's value fit use: a
// permutation of the rollout cut into blocks, every column of a sample kept together, and — when
// asked — each block's advantages standardised on their own: Â ← (Â − mean) / (std + 1e-8), std
// with n − 1.
#include "tendril/rl/rollout_minibatches.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tendril::rl {
namespace {

// Ten steps of two environments, every step its own episode, so Â = r − V and R = r; the single
// observation and the action are the sample's row index, so the gathering can be traced.
RolloutBuffer numbered_rollout() {
  RolloutBuffer buffer(10, 2, 1, 1);
  Rng rng(3);
  for (int t = 0; t < 10; ++t) {
    RolloutBuffer::RowMatrix observations(2, 1);
    observations << 2.0f * t, 2.0f * t + 1;
    Eigen::MatrixXf actions(1, 2);
    actions << 2.0f * t, 2.0f * t + 1;
    Eigen::VectorXf rewards(2), values(2), log_probs(2);
    for (int e = 0; e < 2; ++e) {
      rewards[e] = static_cast<float>(3.0 * rng.normal() + 1.0);
      values[e] = static_cast<float>(rng.normal());
      log_probs[e] = -static_cast<float>(2 * t + e) / 10.0f;
    }
    buffer.add(observations, actions, rewards, values, log_probs, {1, 1}, {0, 0},
               Eigen::VectorXf::Zero(2));
  }
  buffer.finish(Eigen::VectorXf::Zero(2), 0.99, 0.95);
  return buffer;
}

TEST(RolloutMinibatches, AreAShuffledPartitionWithEachBlockStandardisedOnItsOwn) {
  const RolloutBuffer buffer = numbered_rollout();
  RolloutMinibatches minibatches(buffer, 6);
  ASSERT_EQ(minibatches.count(), 4);  // 6 + 6 + 6 + 2
  Rng rng(11);
  std::vector<std::vector<int>> orders;
  for (int epoch = 0; epoch < 2; ++epoch) {
    minibatches.shuffle(rng, /*normalize_advantages=*/true);
    std::vector<int> seen(20, 0), order;
    for (int64_t b = 0; b < minibatches.count(); ++b) {
      const RolloutMinibatch batch = minibatches[b];
      const Eigen::Index n = batch.observations.cols();
      ASSERT_EQ(n, b < 3 ? 6 : 2);
      double mean = 0.0;
      std::vector<int> rows;
      for (Eigen::Index i = 0; i < n; ++i) {
        const int row = static_cast<int>(batch.observations(0, i));
        rows.push_back(row);
        order.push_back(row);
        ++seen[row];
        EXPECT_EQ(batch.actions(0, i), static_cast<float>(row));
        EXPECT_EQ(batch.old_log_probs[i], buffer.log_probs()[row]);
        EXPECT_EQ(batch.old_values[i], buffer.values()[row]);
        EXPECT_EQ(batch.returns[i], buffer.returns()[row]);
        mean += buffer.advantages()[row] / static_cast<double>(n);
      }
      double squares = 0.0;
      for (int row : rows) squares += std::pow(buffer.advantages()[row] - mean, 2);
      const double std = std::sqrt(squares / static_cast<double>(n - 1));
      double standardised_mean = 0.0, standardised_squares = 0.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double expected = (buffer.advantages()[rows[i]] - mean) / (std + 1e-8);
        EXPECT_NEAR(batch.advantages[i], expected, 1e-5) << "minibatch " << b << ", sample " << i;
        standardised_mean += batch.advantages[i] / static_cast<double>(n);
        standardised_squares += std::pow(batch.advantages[i], 2);
      }
      EXPECT_NEAR(standardised_mean, 0.0, 1e-6);
      EXPECT_NEAR(standardised_squares / static_cast<double>(n - 1), 1.0, 1e-5);
    }
    for (int row = 0; row < 20; ++row) EXPECT_EQ(seen[row], 1) << "row " << row;
    orders.push_back(order);
  }
  EXPECT_NE(orders[0], orders[1]);  // a fresh order every epoch

  // Without standardisation the advantages are gathered as they are.
  minibatches.shuffle(rng, /*normalize_advantages=*/false);
  for (int64_t b = 0; b < minibatches.count(); ++b) {
    const RolloutMinibatch batch = minibatches[b];
    for (Eigen::Index i = 0; i < batch.observations.cols(); ++i) {
      const int row = static_cast<int>(batch.observations(0, i));
      EXPECT_EQ(batch.advantages[i], buffer.advantages()[row]);
    }
  }
}

// A minibatch of one sample cannot be standardised (SB3 skips it): it is left as it is.
TEST(RolloutMinibatches, ASingleSampleRemainderIsLeftAsItIs) {
  const RolloutBuffer buffer = numbered_rollout();
  RolloutMinibatches minibatches(buffer, 19);
  ASSERT_EQ(minibatches.count(), 2);
  Rng rng(2);
  minibatches.shuffle(rng, true);
  const RolloutMinibatch last = minibatches[1];
  ASSERT_EQ(last.advantages.size(), 1);
  EXPECT_EQ(last.advantages[0], buffer.advantages()[static_cast<int>(last.observations(0, 0))]);
}

}  // namespace
}  // namespace tendril::rl
