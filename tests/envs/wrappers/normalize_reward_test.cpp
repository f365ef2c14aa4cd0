#include "tendril/envs/wrappers/normalize_reward.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../scripted_env.hpp"
#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

using testing::ScriptedEnv;

const Action kAction = Eigen::Vector2f(0.0f, 0.5f);

// 1 / sqrt(var + 1e-8), clipped to 10: how a reward of 1 is scaled.
double scaled_unit_reward(double variance) {
  return std::min(10.0, 1.0 / std::sqrt(variance + 1e-8));
}

// Pooled variance of SB3's prior (count 1e-4, mean 0, var 1) and `samples`.
double pooled_variance(const std::vector<double>& samples) {
  double n = 1e-4, sum = 0.0;
  for (double x : samples) {
    n += 1.0;
    sum += x;
  }
  const double mean = sum / n;
  double m2 = 1e-4 * (1.0 + mean * mean);
  for (double x : samples) m2 += (x - mean) * (x - mean);
  return m2 / n;
}

// A constant reward of 1 over a 5-step episode: the discounted returns are R_k = Σ_{j<k} 0.99^j
// and reward k is scaled by 1 / sqrt(var(R_1..R_k) + 1e-8), clipped to 10 (the first step's
// variance, of one sample and the prior, is tiny); R restarts after the episode.
TEST(NormalizeReward, ConstantRewardEpisodeMatchesHandComputedScaling) {
  NormalizeReward env(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{1.0, 5}));
  env.reset(0);
  std::vector<double> returns;
  double discounted = 0.0;
  for (int k = 1; k <= 5; ++k) {
    const Step step = env.step(kAction);
    discounted = 0.99 * discounted + 1.0;
    returns.push_back(discounted);
    ASSERT_NEAR(step.reward, scaled_unit_reward(pooled_variance(returns)), 1e-9) << k;
    ASSERT_EQ(step.terminated, k == 5);
    const bool below_clip = step.reward < 10.0;
    ASSERT_EQ(below_clip, k > 1) << k;  // only the first is clipped
  }
  EXPECT_NEAR(returns.back(), 1.0 + 0.99 + 0.9801 + 0.970299 + 0.96059601, 1e-12);
  EXPECT_EQ(env.discounted_return(), 0.0);  // reset at the episode's end

  // Stepping on (as a vector env's auto-reset would, via reset) starts a fresh return of 1.
  env.reset();
  const Step next = env.step(kAction);
  returns.push_back(1.0);
  EXPECT_NEAR(next.reward, scaled_unit_reward(pooled_variance(returns)), 1e-9);
  EXPECT_EQ(env.discounted_return(), 1.0);
}

TEST(NormalizeReward, ClipsAndKeepsTheSign) {
  NormalizeReward env(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{-1000.0, 0}));
  RunningMeanStd stats(1);
  stats.update_from_moments(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 4.0), 100.0);
  env.set_statistics(stats);
  env.set_training(false);
  EXPECT_NEAR(env.normalize(3.0), 3.0 / std::sqrt(stats.var()[0] + 1e-8), 1e-12);
  env.reset(0);
  EXPECT_EQ(env.step(kAction).reward, -10.0);  // −1000 / 2, clipped
}

TEST(NormalizeReward, FrozenStatisticsAndExactRoundTrip) {
  NormalizeReward trained(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{0.7, 3}));
  trained.reset(0);
  for (int t = 0; t < 10; ++t) {
    if (trained.step(kAction).terminated) trained.reset();
  }
  const std::vector<double> saved = trained.export_statistics();
  ASSERT_EQ(saved.size(), 3u);

  NormalizeReward evaluation(std::make_unique<ScriptedEnv>(ScriptedEnv::Options{0.7, 3}));
  evaluation.import_statistics(saved);
  evaluation.set_training(false);
  evaluation.reset(0);
  const Step step = evaluation.step(kAction);
  EXPECT_EQ(step.reward, trained.normalize(0.7));
  EXPECT_EQ(evaluation.export_statistics(), saved);  // frozen
  EXPECT_EQ(evaluation.discounted_return(), 0.0);

  EXPECT_THROW(evaluation.import_statistics(std::vector<double>{1.0, 0.0}), Error);
  EXPECT_THROW(NormalizeReward(std::make_unique<ScriptedEnv>(), NormalizeReward::Options{1.5}),
               Error);
}

}  // namespace
}  // namespace tendril::envs
