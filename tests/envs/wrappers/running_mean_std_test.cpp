#include "tendril/envs/wrappers/running_mean_std.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::envs {
namespace {

// The running statistics equal the pooled statistics of the prior (count 1e-4, mean 0, var 1)
// and the samples: n = Σcount, mean = Σ count·mean / n, var = Σ count (var + (mean_i − mean)²) / n.
TEST(RunningMeanStd, EqualsThePooledStatisticsOfPriorAndSamples) {
  const std::vector<double> samples = {3.0, -1.0, 4.0, 1.5, 9.0};
  RunningMeanStd stats(1);
  for (double x : samples) stats.update(Eigen::VectorXd::Constant(1, x));
  const double prior = 1e-4;
  double n = prior, sum = 0.0;
  for (double x : samples) {
    n += 1.0;
    sum += x;
  }
  const double mean = sum / n;
  double m2 = prior * (1.0 + mean * mean);
  for (double x : samples) m2 += (x - mean) * (x - mean);
  EXPECT_DOUBLE_EQ(stats.count(), n);
  EXPECT_NEAR(stats.mean()[0], mean, 1e-12);
  EXPECT_NEAR(stats.var()[0], m2 / n, 1e-12);
}

TEST(RunningMeanStd, MergeEqualsFeedingAllSamplesToOne) {
  RunningMeanStd a(2), b(2), all(2);
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector2d x(i * 0.5, -i * i);
    (i < 3 ? a : b).update(x);
    all.update(x);
  }
  a.merge(b);
  // Both priors are pooled in by the merge, the single stream has only one.
  EXPECT_NEAR(a.count(), all.count() + RunningMeanStd::kInitialCount, 1e-12);
  EXPECT_TRUE(a.mean().isApprox(all.mean(), 1e-4));
  EXPECT_TRUE(a.var().isApprox(all.var(), 1e-4));
}

TEST(RunningMeanStd, ArrayRoundTripIsExactAndValidated) {
  RunningMeanStd stats(3);
  stats.update(Eigen::Vector3d(0.1, 0.2, 0.3));
  stats.update(Eigen::Vector3d(1.0 / 3.0, -7.0, 1e9));
  const std::vector<double> values = stats.to_array();
  ASSERT_EQ(values.size(), 7u);
  EXPECT_EQ(values[0], stats.count());
  EXPECT_EQ(RunningMeanStd::from_array(values, 3), stats);
  EXPECT_THROW(RunningMeanStd::from_array(values, 2), Error);
  std::vector<double> negative = values;
  negative[5] = -1.0;
  EXPECT_THROW(RunningMeanStd::from_array(negative, 3), Error);
  std::vector<double> zero_count = values;
  zero_count[0] = 0.0;
  EXPECT_THROW(RunningMeanStd::from_array(zero_count, 3), Error);
}

}  // namespace
}  // namespace tendril::envs
