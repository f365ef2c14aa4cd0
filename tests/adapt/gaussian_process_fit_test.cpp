// Hyper-parameter search, jitter and bad input of GaussianProcess.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/error_message.hpp"
#include "tendril/adapt/cholesky.hpp"
#include "tendril/adapt/gaussian_process.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// y = sin(2 x₀) + 𝒩(0, 0.1²) on [−2, 2]²: the second input is irrelevant.
struct RelevanceData {
  Eigen::MatrixXd inputs;
  Eigen::VectorXd targets;
};
RelevanceData relevance_data(int n, uint64_t seed) {
  Rng rng(seed);
  RelevanceData data{Eigen::MatrixXd(n, 2), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    data.inputs(i, 0) = rng.uniform(-2.0, 2.0);
    data.inputs(i, 1) = rng.uniform(-2.0, 2.0);
    data.targets[i] = std::sin(2.0 * data.inputs(i, 0)) + 0.1 * rng.normal();
  }
  return data;
}

TEST(GaussianProcessFit, MaximumLikelihoodFindsRelevanceAndNoise) {
  for (KernelType kernel : {KernelType::squared_exponential, KernelType::matern52}) {
    const RelevanceData data = relevance_data(120, 1);
    GpOptions options;
    options.kernel = kernel;
    GaussianProcess gp(2, options);
    gp.fit(data.inputs, data.targets);
    const double initial = gp.log_marginal_likelihood();
    Rng rng(2);
    const double best = gp.optimize_hyperparameters(rng);
    EXPECT_DOUBLE_EQ(best, gp.log_marginal_likelihood());
    EXPECT_GT(best, initial);
    const auto& hyper = gp.hyperparameters();
    // The irrelevant input's length scale grows far beyond the relevant one's (ARD), and the
    // noise variance lands near the 0.01 that generated the data.
    EXPECT_GT(hyper.length_scales[1], 10.0 * hyper.length_scales[0]) << kernel_type_name(kernel);
    EXPECT_GT(hyper.noise_variance, 0.005) << kernel_type_name(kernel);
    EXPECT_LT(hyper.noise_variance, 0.02) << kernel_type_name(kernel);
    // A maximum: the gradient vanishes in every coordinate not held at a bound.
    Eigen::VectorXd gradient;
    const Eigen::VectorXd theta = GaussianProcess::to_log_parameters(hyper);
    gp.log_marginal_likelihood(theta, &gradient);
    for (int k : {0, 2, 3}) EXPECT_LT(std::abs(gradient[k]), 1e-2) << "parameter " << k;
    const bool at_upper_bound = hyper.length_scales[1] > 0.999 * options.max_length_scale;
    EXPECT_TRUE(at_upper_bound || std::abs(gradient[1]) < 1e-2);
    // Predictions follow the function.
    Eigen::MatrixXd queries(3, 2);
    queries << 0.3, -1.0, -0.7, 0.5, 1.2, 1.9;
    Eigen::VectorXd mean, variance;
    gp.predict(queries, mean, variance);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean[i], std::sin(2.0 * queries(i, 0)), 0.1);
  }
}

TEST(GaussianProcessFit, SameSeedGivesSameHyperparameters) {
  const RelevanceData data = relevance_data(60, 3);
  GpOptions options;
  options.restarts = 4;
  GaussianProcess first(2, options), second(2, options);
  first.fit(data.inputs, data.targets);
  second.fit(data.inputs, data.targets);
  Rng rng_first(11), rng_second(11);
  first.optimize_hyperparameters(rng_first);
  second.optimize_hyperparameters(rng_second);
  EXPECT_EQ(GaussianProcess::to_log_parameters(first.hyperparameters()),
            GaussianProcess::to_log_parameters(second.hyperparameters()));
  EXPECT_EQ(rng_first.state(), rng_second.state());
}

TEST(GaussianProcessFit, TargetScaleDoesNotChangeTheSearch) {
  // The variance bounds are relative to the targets' variance: targets in other units give the
  // same length scales and variances scaled by the unit squared.
  const RelevanceData data = relevance_data(50, 4);
  GaussianProcess unit(2), milli(2);
  unit.fit(data.inputs, data.targets);
  milli.fit(data.inputs, 1000.0 * data.targets);
  milli.set_hyperparameters({Eigen::Vector2d::Ones(), 1e6, 1e4});
  Rng rng_unit(5), rng_milli(5);
  unit.optimize_hyperparameters(rng_unit);
  milli.optimize_hyperparameters(rng_milli);
  const auto& a = unit.hyperparameters();
  const auto& b = milli.hyperparameters();
  EXPECT_NEAR(b.length_scales[0], a.length_scales[0], 1e-3 * a.length_scales[0]);
  EXPECT_NEAR(b.signal_variance / 1e6, a.signal_variance, 1e-3 * a.signal_variance);
  EXPECT_NEAR(b.noise_variance / 1e6, a.noise_variance, 1e-3 * a.noise_variance);
}

TEST(GaussianProcessFit, JitterRescuesDuplicateInputsWithoutNoise) {
  GaussianProcess gp(1, {}, {Eigen::VectorXd::Ones(1), 1.0, 0.0});
  Eigen::MatrixXd x(3, 1);
  x << 0.0, 0.0, 1.0;
  gp.fit(x, Eigen::Vector3d(1.0, 1.0, 2.0));
  EXPECT_GT(gp.jitter(), 0.0);
  EXPECT_LE(gp.jitter(), kLastJitter);
  Eigen::VectorXd mean, variance;
  gp.predict(Eigen::MatrixXd::Zero(1, 1), mean, variance);
  EXPECT_NEAR(mean[0], 1.0, 1e-4);
  // Adding yet another duplicate extends the factor or refactors; either way it stays valid.
  gp.add(Eigen::VectorXd::Zero(1), 1.0);
  gp.predict(Eigen::MatrixXd::Zero(1, 1), mean, variance);
  EXPECT_NEAR(mean[0], 1.0, 1e-4);
  EXPECT_TRUE(variance.allFinite());
}

TEST(GaussianProcessFit, IndefiniteMatrixDefeatsTheJitterLadder) {
  Eigen::Matrix2d indefinite;
  indefinite << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1
  Eigen::MatrixXd factor(2, 2);
  double jitter = 0.0;
  EXPECT_FALSE(factor_with_jitter(indefinite, 0.0, 1.0, factor, jitter));
  EXPECT_TRUE(factor_with_jitter(indefinite, 1.5, 1.0, factor, jitter));  // now [[2.5,2],[2,2.5]]
  EXPECT_EQ(jitter, 0.0);
}

TEST(GaussianProcessFit, UnfactorableKernelIsAnError) {
  // A signal variance so small (subnormal) that every rung of jitter underflows to zero: the
  // duplicate inputs leave the matrix singular and the GP says so.
  GaussianProcess gp(1, {}, {Eigen::VectorXd::Ones(1), 1e-320, 0.0});
  Eigen::MatrixXd x(2, 1);
  x << 0.5, 0.5;
  const std::string message = error_message([&] { gp.fit(x, Eigen::Vector2d(1.0, 1.0)); });
  EXPECT_TRUE(contains(message, "not positive definite even with jitter")) << message;
  EXPECT_EQ(gp.size(), 0);
  // Hyper-parameters that cannot factor the data held leave the previous ones in force.
  GaussianProcess held(1, {}, {Eigen::VectorXd::Ones(1), 1.0, 0.0});
  held.fit(x, Eigen::Vector2d(1.0, 1.0));
  EXPECT_TRUE(contains(error_message([&] {
                         held.set_hyperparameters({Eigen::VectorXd::Ones(1), 1e-320, 0.0});
                       }),
                       "not positive definite"));
  EXPECT_EQ(held.hyperparameters().signal_variance, 1.0);
  EXPECT_EQ(held.size(), 2);
  Eigen::VectorXd mean, variance;
  held.predict(x, mean, variance);
  EXPECT_NEAR(mean[0], 1.0, 1e-6);
}

TEST(GaussianProcessFit, BadInputIsAnErrorNamingIt) {
  GaussianProcess gp(2);
  Eigen::MatrixXd x = Eigen::MatrixXd::Random(4, 2);
  Eigen::VectorXd y = Eigen::VectorXd::Ones(4);
  y[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(error_message([&] { gp.fit(x, y); }), "target 3 is nan"));
  EXPECT_TRUE(contains(error_message([&] { gp.fit(x, Eigen::VectorXd::Ones(3)); }),
                       "4 inputs but 3 targets"));
  EXPECT_TRUE(contains(error_message([&] { gp.fit(Eigen::MatrixXd::Ones(4, 3), y); }),
                       "3 columns, expected 2"));
  x(1, 0) = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(error_message([&] { gp.fit(x, Eigen::VectorXd::Ones(4)); }),
                       "input 1 is not finite"));
  EXPECT_EQ(gp.size(), 0);  // nothing was taken from the rejected data

  EXPECT_TRUE(contains(error_message([&] { gp.add(Eigen::VectorXd::Ones(3), 1.0); }),
                       "input has 3 values, expected 2"));
  EXPECT_TRUE(
      contains(error_message([&] { gp.add(Eigen::VectorXd::Ones(2), NAN); }), "target is nan"));
  Eigen::VectorXd mean, variance;
  EXPECT_TRUE(
      contains(error_message([&] { gp.predict(Eigen::MatrixXd::Ones(2, 1), mean, variance); }),
               "1 columns, expected 2"));
  EXPECT_TRUE(contains(
      error_message([&] { gp.predict(Eigen::MatrixXd::Constant(1, 2, NAN), mean, variance); }),
      "not finite"));
  Rng rng(0);
  EXPECT_TRUE(contains(error_message([&] { gp.optimize_hyperparameters(rng); }), "no data"));
  EXPECT_TRUE(contains(error_message([&] {
                         gp.set_hyperparameters({Eigen::VectorXd::Ones(3), 1.0, 0.1});
                       }),
                       "3 length scales for an input of dimension 2"));
  EXPECT_TRUE(contains(error_message([&] {
                         gp.set_hyperparameters({Eigen::Vector2d(1.0, -1.0), 1.0, 0.1});
                       }),
                       "length scale 1"));
  EXPECT_TRUE(contains(error_message([&] {
                         gp.set_hyperparameters({Eigen::Vector2d::Ones(), 1.0, -0.1});
                       }),
                       "noise variance"));
  EXPECT_TRUE(
      contains(error_message([&] { gp.log_marginal_likelihood(Eigen::VectorXd(3), nullptr); }),
               "3 log-parameters, expected 4"));
  GpOptions bad_bounds;
  bad_bounds.min_length_scale = 2.0;
  bad_bounds.max_length_scale = 1.0;
  EXPECT_TRUE(contains(error_message([&] { GaussianProcess(2, bad_bounds); }), "bounds"));
  EXPECT_TRUE(contains(error_message([] { kernel_type_from_name("rbf", "gp.kernel"); }),
                       "gp.kernel: unknown kernel 'rbf'"));
}

}  // namespace
}  // namespace tendril::adapt
