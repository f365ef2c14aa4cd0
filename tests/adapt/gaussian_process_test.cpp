#include "tendril/adapt/gaussian_process.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "support/error_message.hpp"
#include "tendril/adapt/cholesky.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

Eigen::MatrixXd random_inputs(int n, int d, Rng& rng, double low = -2.0, double high = 2.0) {
  Eigen::MatrixXd x(n, d);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < d; ++j) x(i, j) = rng.uniform(low, high);
  }
  return x;
}

// A smooth function of every input plus noise.
Eigen::VectorXd smooth_targets(const Eigen::MatrixXd& x, Rng& rng, double noise = 0.05) {
  Eigen::VectorXd y(x.rows());
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    double value = 0.0;
    for (Eigen::Index j = 0; j < x.cols(); ++j) value += std::sin((j + 1) * x(i, j)) / (j + 1);
    y[i] = value + noise * rng.normal();
  }
  return y;
}

GpOptions options_for(KernelType kernel) {
  GpOptions options;
  options.kernel = kernel;
  return options;
}

class BothKernels : public ::testing::TestWithParam<KernelType> {};
INSTANTIATE_TEST_SUITE_P(Kernels, BothKernels,
                         ::testing::Values(KernelType::squared_exponential, KernelType::matern52),
                         [](const auto& info) { return kernel_type_name(info.param); });

// Two points x = 0, 1 with targets 1, −1, zero prior mean, ℓ = 1, σ_f² = 1, σ_n² = 0.01:
// K + σ_n² I = [[a, b], [b, a]] with a = 1.01, b = k(1), whose inverse is
// [[a, −b], [−b, a]] / (a² − b²). Posterior at x* = 2 (R&W eq. 2.25–2.26):
//   mean = k*ᵀ K⁻¹ y = (k(2) − k(1)) / (a − b)
//   variance = 1 − (a k(2)² − 2 b k(2) k(1) + a k(1)²) / (a² − b²)
//   log p(y) = −yᵀK⁻¹y/2 − log(a² − b²)/2 − log 2π, with yᵀK⁻¹y = 2/(a − b).
TEST_P(BothKernels, TwoPointPosteriorMatchesClosedForm) {
  const KernelType type = GetParam();
  GpOptions options = options_for(type);
  options.mean_of_targets = false;
  GaussianProcess gp(1, options, {Eigen::VectorXd::Ones(1), 1.0, 0.01});
  Eigen::MatrixXd x(2, 1);
  x << 0.0, 1.0;
  gp.fit(x, Eigen::Vector2d(1.0, -1.0));

  const double a = 1.01, b = ArdKernel::shape(type, 1.0), k2 = ArdKernel::shape(type, 2.0);
  Eigen::VectorXd mean, variance, noisy_variance;
  gp.predict(Eigen::MatrixXd::Constant(1, 1, 2.0), mean, variance);
  gp.predict(Eigen::MatrixXd::Constant(1, 1, 2.0), mean, noisy_variance, true);
  EXPECT_NEAR(mean[0], (k2 - b) / (a - b), 1e-14);
  const double expected_variance =
      1.0 - (a * k2 * k2 - 2 * b * k2 * b + a * b * b) / (a * a - b * b);
  EXPECT_NEAR(variance[0], expected_variance, 1e-14);
  EXPECT_NEAR(noisy_variance[0], expected_variance + 0.01, 1e-14);
  EXPECT_NEAR(gp.log_marginal_likelihood(),
              -1.0 / (a - b) - 0.5 * std::log(a * a - b * b) - std::log(2 * std::numbers::pi),
              1e-13);
}

// Three 2-D points, ARD length scales (0.5, 2), σ_f² = 1.5, σ_n² = 0.1, the prior mean at the
// targets' mean (7/3). Expected values from R&W eq. 2.25–2.26 and 2.30 evaluated with NumPy
// (numpy.linalg.solve and slogdet on the 3 × 3 matrix).
TEST_P(BothKernels, ThreePointPosteriorMatchesDirectSolve) {
  const KernelType type = GetParam();
  GaussianProcess gp(2, options_for(type), {Eigen::Vector2d(0.5, 2.0), 1.5, 0.1});
  Eigen::MatrixXd x(3, 2);
  x << 0, 0, 1, 0, 0, 1;
  gp.fit(x, Eigen::Vector3d(1, 2, 4));
  Eigen::MatrixXd queries(2, 2);
  queries << 0.5, 0.5, 2.0, -1.0;
  Eigen::VectorXd mean, variance;
  gp.predict(queries, mean, variance);
  const bool se = type == KernelType::squared_exponential;
  const Eigen::Vector2d expected_mean = se ? Eigen::Vector2d(2.32399876649522, 2.30695264979881)
                                           : Eigen::Vector2d(2.30639126236972, 2.29619777176982);
  const Eigen::Vector2d expected_variance =
      se ? Eigen::Vector2d(0.594779900382741, 1.47962189421535)
         : Eigen::Vector2d(0.822454710263778, 1.47733479919487);
  EXPECT_LT((mean - expected_mean).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((variance - expected_variance).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(gp.log_marginal_likelihood(), se ? -11.0471683468296 : -9.32695566894662, 1e-11);
  EXPECT_DOUBLE_EQ(gp.prior_mean(), 7.0 / 3.0);
}

TEST_P(BothKernels, LikelihoodGradientMatchesFiniteDifferences) {
  Rng rng(3);
  const Eigen::MatrixXd x = random_inputs(25, 3, rng);
  GaussianProcess gp(3, options_for(GetParam()));
  gp.fit(x, smooth_targets(x, rng));
  Eigen::VectorXd theta(5);
  theta << std::log(0.7), std::log(1.9), std::log(0.4), std::log(0.8), std::log(0.02);
  Eigen::VectorXd gradient;
  const double value = gp.log_marginal_likelihood(theta, &gradient);
  EXPECT_DOUBLE_EQ(value, gp.log_marginal_likelihood(theta, nullptr));
  const double h = 1e-5;
  for (int k = 0; k < theta.size(); ++k) {
    Eigen::VectorXd plus = theta, minus = theta;
    plus[k] += h;
    minus[k] -= h;
    const double numeric =
        (gp.log_marginal_likelihood(plus, nullptr) - gp.log_marginal_likelihood(minus, nullptr)) /
        (2 * h);
    EXPECT_NEAR(gradient[k], numeric, 1e-6 * (1.0 + std::abs(numeric))) << "parameter " << k;
  }
}

TEST_P(BothKernels, PredictionGradientsMatchFiniteDifferences) {
  Rng rng(4);
  const Eigen::MatrixXd x = random_inputs(15, 2, rng);
  GaussianProcess gp(2, options_for(GetParam()), {Eigen::Vector2d(0.8, 1.3), 1.2, 0.01});
  gp.fit(x, smooth_targets(x, rng));
  const Eigen::Vector2d query(0.3, -0.45);
  double mean, variance;
  Eigen::VectorXd mean_gradient, variance_gradient;
  gp.predict(query, mean, variance, mean_gradient, variance_gradient);
  Eigen::VectorXd batch_mean, batch_variance;
  gp.predict(query.transpose(), batch_mean, batch_variance);
  EXPECT_NEAR(mean, batch_mean[0], 1e-13);
  EXPECT_NEAR(variance, batch_variance[0], 1e-13);
  const double h = 1e-6;
  for (int j = 0; j < 2; ++j) {
    Eigen::VectorXd m_plus, v_plus, m_minus, v_minus;
    Eigen::RowVector2d plus = query.transpose(), minus = query.transpose();
    plus[j] += h;
    minus[j] -= h;
    gp.predict(plus, m_plus, v_plus);
    gp.predict(minus, m_minus, v_minus);
    EXPECT_NEAR(mean_gradient[j], (m_plus[0] - m_minus[0]) / (2 * h), 1e-7);
    EXPECT_NEAR(variance_gradient[j], (v_plus[0] - v_minus[0]) / (2 * h), 1e-7);
  }
}

TEST_P(BothKernels, IncrementalAdditionEqualsRefit) {
  Rng rng(5);
  const Eigen::MatrixXd x = random_inputs(40, 3, rng);
  const Eigen::VectorXd y = smooth_targets(x, rng);
  const GpHyperparameters hyper{Eigen::Vector3d(0.6, 1.1, 2.0), 0.9, 0.003};
  GaussianProcess incremental(3, options_for(GetParam()), hyper);
  incremental.fit(x.topRows(10), y.head(10));
  for (int i = 10; i < 40; ++i) incremental.add(x.row(i).transpose(), y[i]);
  GaussianProcess refit(3, options_for(GetParam()), hyper);
  refit.fit(x, y);

  ASSERT_EQ(incremental.size(), 40);
  EXPECT_EQ(incremental.jitter(), 0.0);
  const Eigen::MatrixXd l_incremental =
      incremental.cholesky_factor().triangularView<Eigen::Lower>();
  const Eigen::MatrixXd l_refit = refit.cholesky_factor().triangularView<Eigen::Lower>();
  EXPECT_LT((l_incremental - l_refit).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(incremental.log_marginal_likelihood(), refit.log_marginal_likelihood(), 1e-10);
  const Eigen::MatrixXd queries = random_inputs(20, 3, rng);
  Eigen::VectorXd m1, v1, m2, v2;
  incremental.predict(queries, m1, v1);
  refit.predict(queries, m2, v2);
  EXPECT_LT((m1 - m2).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((v1 - v2).cwiseAbs().maxCoeff(), 1e-10);
}

TEST_P(BothKernels, SlidingWindowEqualsFitOnWindow) {
  Rng rng(6);
  const Eigen::MatrixXd x = random_inputs(60, 2, rng);
  const Eigen::VectorXd y = smooth_targets(x, rng);
  GpOptions options = options_for(GetParam());
  options.window = 15;
  const GpHyperparameters hyper{Eigen::Vector2d(0.5, 0.9), 1.3, 0.002};
  GaussianProcess sliding(2, options, hyper);
  for (int i = 0; i < 60; ++i) sliding.add(x.row(i).transpose(), y[i]);
  GaussianProcess on_window(2, options_for(GetParam()), hyper);
  on_window.fit(x.bottomRows(15), y.tail(15));
  GaussianProcess fit_past_window(2, options, hyper);
  fit_past_window.fit(x, y);  // keeps the last 15

  ASSERT_EQ(sliding.size(), 15);
  ASSERT_EQ(fit_past_window.size(), 15);
  EXPECT_EQ(sliding.inputs(), x.bottomRows(15));
  EXPECT_EQ(sliding.targets(), y.tail(15));
  const Eigen::MatrixXd l_sliding = sliding.cholesky_factor().triangularView<Eigen::Lower>();
  const Eigen::MatrixXd l_window = on_window.cholesky_factor().triangularView<Eigen::Lower>();
  EXPECT_LT((l_sliding - l_window).cwiseAbs().maxCoeff(), 1e-11);
  const Eigen::MatrixXd queries = random_inputs(20, 2, rng);
  Eigen::VectorXd m1, v1, m2, v2, m3, v3;
  sliding.predict(queries, m1, v1);
  on_window.predict(queries, m2, v2);
  fit_past_window.predict(queries, m3, v3);
  EXPECT_LT((m1 - m2).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((v1 - v2).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((m3 - m2).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(sliding.log_marginal_likelihood(), on_window.log_marginal_likelihood(), 1e-10);
}

TEST(GaussianProcess, RemovingEveryPointLeavesThePrior) {
  GaussianProcess gp(1);
  gp.add(Eigen::VectorXd::Constant(1, 0.5), 2.0);
  gp.add(Eigen::VectorXd::Constant(1, -0.5), 1.0);
  gp.remove_oldest();
  gp.remove_oldest();
  EXPECT_EQ(gp.size(), 0);
  Eigen::VectorXd mean, variance;
  gp.predict(Eigen::MatrixXd::Zero(1, 1), mean, variance);
  EXPECT_EQ(mean[0], 0.0);
  EXPECT_EQ(variance[0], gp.hyperparameters().signal_variance);
  EXPECT_NE(error_message([&] { gp.remove_oldest(); }).find("no point to remove"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::adapt
