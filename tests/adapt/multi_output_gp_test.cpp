#include "tendril/adapt/multi_output_gp.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/error_message.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

// Output 0 depends on the first input only, output 1 on the second only.
void make_data(int n, Rng& rng, Eigen::MatrixXd& inputs, Eigen::MatrixXd& targets) {
  inputs.resize(n, 2);
  targets.resize(n, 2);
  for (int i = 0; i < n; ++i) {
    inputs(i, 0) = rng.uniform(-2.0, 2.0);
    inputs(i, 1) = rng.uniform(-2.0, 2.0);
    targets(i, 0) = std::sin(2.0 * inputs(i, 0)) + 0.05 * rng.normal();
    targets(i, 1) = 10.0 * std::cos(inputs(i, 1)) + 0.5 * rng.normal();
  }
}

TEST(MultiOutputGp, EachOutputIsAnIndependentGp) {
  Rng rng(1);
  Eigen::MatrixXd x, y;
  make_data(30, rng, x, y);
  MultiOutputGp gp(2, 2);
  gp.fit(x.topRows(20), y.topRows(20));
  for (int i = 20; i < 30; ++i) gp.add(x.row(i).transpose(), y.row(i).transpose());
  Eigen::MatrixXd queries = Eigen::MatrixXd::Random(5, 2), mean, variance;
  gp.predict(queries, mean, variance, true);
  for (int k = 0; k < 2; ++k) {
    GaussianProcess single(2);
    single.fit(x, y.col(k));
    Eigen::VectorXd single_mean, single_variance;
    single.predict(queries, single_mean, single_variance, true);
    EXPECT_LT((mean.col(k) - single_mean).cwiseAbs().maxCoeff(), 1e-10);
    EXPECT_LT((variance.col(k) - single_variance).cwiseAbs().maxCoeff(), 1e-10);
  }
}

TEST(MultiOutputGp, OutputsFitTheirOwnHyperparametersReproducibly) {
  Rng data_rng(2);
  Eigen::MatrixXd x, y;
  make_data(80, data_rng, x, y);
  MultiOutputGp first(2, 2), second(2, 2);
  first.fit(x, y);
  second.fit(x, y);
  Rng rng_first(9), rng_second(9);
  const double total = first.optimize_hyperparameters(rng_first);
  EXPECT_DOUBLE_EQ(total, second.optimize_hyperparameters(rng_second));
  EXPECT_NEAR(total,
              first.output(0).log_marginal_likelihood() + first.output(1).log_marginal_likelihood(),
              1e-9);
  const auto& h0 = first.output(0).hyperparameters();
  const auto& h1 = first.output(1).hyperparameters();
  EXPECT_GT(h0.length_scales[1], 10.0 * h0.length_scales[0]);  // output 0 ignores input 1
  EXPECT_GT(h1.length_scales[0], 10.0 * h1.length_scales[1]);  // output 1 ignores input 0
  EXPECT_GT(h1.noise_variance, 50.0 * h0.noise_variance);      // 0.25 against 0.0025
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(GaussianProcess::to_log_parameters(first.output(k).hyperparameters()),
              GaussianProcess::to_log_parameters(second.output(k).hyperparameters()));
  }
}

TEST(MultiOutputGp, SharedHyperparametersScaleWithEachOutput) {
  Rng data_rng(4);
  Eigen::MatrixXd x, y;
  make_data(60, data_rng, x, y);
  y.col(1) = (100.0 * y.col(0).array() + 5.0).matrix();  // the same function in other units
  MultiOutputGp gp(2, 2, {}, HyperparameterSharing::shared),
      again(2, 2, {}, HyperparameterSharing::shared);
  gp.fit(x, y);
  again.fit(x, y);
  const double before =
      gp.output(0).log_marginal_likelihood() + gp.output(1).log_marginal_likelihood();
  Rng rng(5), rng_again(5);
  const double after = gp.optimize_hyperparameters(rng);
  EXPECT_GT(after, before);
  EXPECT_DOUBLE_EQ(after, again.optimize_hyperparameters(rng_again));
  const auto& h0 = gp.output(0).hyperparameters();
  const auto& h1 = gp.output(1).hyperparameters();
  EXPECT_EQ(h0.length_scales, h1.length_scales);
  EXPECT_NEAR(h1.signal_variance, 1e4 * h0.signal_variance, 1e-9 * h1.signal_variance);
  EXPECT_NEAR(h1.noise_variance, 1e4 * h0.noise_variance, 1e-9 * h1.noise_variance);
  EXPECT_GT(h0.length_scales[1], 10.0 * h0.length_scales[0]);  // input 1 is irrelevant
  // The predictions of the second output are those of the first, in its units.
  Eigen::MatrixXd queries = Eigen::MatrixXd::Random(4, 2), mean, variance;
  gp.predict(queries, mean, variance);
  EXPECT_LT((mean.col(1) - (100.0 * mean.col(0).array() + 5.0).matrix()).cwiseAbs().maxCoeff(),
            1e-8);
}

TEST(MultiOutputGp, WindowKeepsTheLatestPointsOfEveryOutput) {
  Rng rng(3);
  Eigen::MatrixXd x, y;
  make_data(25, rng, x, y);
  GpOptions options;
  options.window = 10;
  MultiOutputGp gp(2, 2, options);
  for (int i = 0; i < 25; ++i) gp.add(x.row(i).transpose(), y.row(i).transpose());
  EXPECT_EQ(gp.size(), 10);
  for (int k = 0; k < 2; ++k) EXPECT_EQ(gp.output(k).targets(), y.col(k).tail(10));
}

TEST(MultiOutputGp, BadInputIsAnErrorNamingIt) {
  MultiOutputGp gp(2, 3);
  Eigen::MatrixXd targets = Eigen::MatrixXd::Zero(4, 3);
  targets(2, 1) = NAN;
  const auto message = [&](auto action) { return error_message(action); };
  EXPECT_NE(message([&] {
              gp.fit(Eigen::MatrixXd::Zero(4, 2), targets);
            }).find("target 2 of output 1 is nan"),
            std::string::npos);
  EXPECT_NE(message([&] {
              gp.fit(Eigen::MatrixXd::Zero(4, 2), Eigen::MatrixXd::Zero(4, 2));
            }).find("2 columns, expected 3"),
            std::string::npos);
  EXPECT_NE(message([&] {
              gp.fit(Eigen::MatrixXd::Zero(5, 2), Eigen::MatrixXd::Zero(4, 3));
            }).find("5 inputs but 4 targets"),
            std::string::npos);
  EXPECT_NE(message([&] {
              gp.add(Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(2));
            }).find("2 values, expected 3"),
            std::string::npos);
  EXPECT_NE(message([&] {
              gp.add(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(3));
            }).find("input must be 2 finite values"),
            std::string::npos);
  EXPECT_EQ(gp.size(), 0);
}

}  // namespace
}  // namespace tendril::adapt
