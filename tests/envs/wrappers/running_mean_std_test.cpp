#include "tendril/envs/wrappers/running_mean_std.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// SB3's update(arr): a batch enters with its population mean and variance and its row count.
TEST(RunningMeanStd, BatchUpdateMergesThePopulationMomentsOfTheRows) {
  Eigen::MatrixXd batch(3, 2);
  batch << 1.0, -4.0, 2.0, 0.5, 6.0, 3.0;
  RunningMeanStd stats(2), by_moments(2);
  stats.update_batch(batch);
  const Eigen::Vector2d mean(3.0, -0.5 / 3.0);
  Eigen::Vector2d var;
  var[0] = (4.0 + 1.0 + 9.0) / 3.0;
  var[1] =
      (std::pow(-4.0 - mean[1], 2) + std::pow(0.5 - mean[1], 2) + std::pow(3.0 - mean[1], 2)) / 3.0;
  by_moments.update_from_moments(mean, var, 3.0);
  EXPECT_DOUBLE_EQ(stats.count(), 3.0 + RunningMeanStd::kInitialCount);
  EXPECT_TRUE(stats.mean().isApprox(by_moments.mean(), 1e-14));
  EXPECT_TRUE(stats.var().isApprox(by_moments.var(), 1e-14));
  EXPECT_THROW(stats.update_batch(Eigen::MatrixXd(0, 2)), Error);
}

TEST(RunningMeanStd, NormalizeCentresScalesAndClipsScaleOnlyScales) {
  const RunningMeanStd stats = RunningMeanStd::from_array(std::vector<double>{5.0, 1.0, 4.0}, 1);
  EXPECT_DOUBLE_EQ(stats.normalize(Eigen::VectorXd::Constant(1, 3.0), 0.0, 10.0)[0], 1.0);
  EXPECT_DOUBLE_EQ(stats.normalize(Eigen::VectorXd::Constant(1, 101.0), 0.0, 10.0)[0], 10.0);
  EXPECT_DOUBLE_EQ(stats.normalize(Eigen::VectorXd::Constant(1, -99.0), 0.0, 10.0)[0], -10.0);
  EXPECT_DOUBLE_EQ(stats.scale(3.0, 0.0, 10.0), 1.5);  // not centred: the sign is kept
  EXPECT_DOUBLE_EQ(stats.scale(-30.0, 0.0, 10.0), -10.0);
}

// Unequal halves (2 + 5 samples), so that a merge weighting the two sides wrongly shows. The
// merged statistics pool both priors (count ε, mean 0, variance 1 each) with the seven samples:
//   n = 2ε + 7,  μ = Σ x / n,  σ² = (2ε (1 + μ²) + Σ (x − μ)²) / n.
TEST(RunningMeanStd, MergeEqualsHandPooledStatisticsOfBothSides) {
  constexpr double eps = RunningMeanStd::kInitialCount;
  RunningMeanStd a(2), b(2);
  std::vector<Eigen::Vector2d> samples;
  for (int i = 0; i < 7; ++i) samples.emplace_back(i * 0.5 + 1.0, -i * i);
  for (int i = 0; i < 7; ++i) (i < 2 ? a : b).update(samples[i]);
  a.merge(b);
  const double n = 2 * eps + 7;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& x : samples) mean += x / n;
  Eigen::Vector2d var = 2 * eps * (Eigen::Vector2d::Ones() + mean.cwiseProduct(mean));
  for (const auto& x : samples) var += (x - mean).cwiseProduct(x - mean);
  var /= n;
  EXPECT_NEAR(a.count(), n, 1e-12);
  EXPECT_TRUE(a.mean().isApprox(mean, 1e-12)) << a.mean().transpose() << " vs " << mean.transpose();
  EXPECT_TRUE(a.var().isApprox(var, 1e-12)) << a.var().transpose() << " vs " << var.transpose();
  // Merging the other way round gives the same statistics.
  RunningMeanStd c(2), d(2);
  for (int i = 0; i < 7; ++i) (i < 2 ? c : d).update(samples[i]);
  d.merge(c);
  EXPECT_TRUE(d.mean().isApprox(mean, 1e-12));
  EXPECT_TRUE(d.var().isApprox(var, 1e-12));
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
