#include "tendril/adapt/bayesian_optimizer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/error_message.hpp"

namespace tendril::adapt {
namespace {

using testing::error_message;

// Branin–Hoo on [−5, 10] × [0, 15]: three global minima of 0.397887 (Dixon & Szegő 1978).
double branin(const Eigen::VectorXd& x) {
  const double pi = std::numbers::pi;
  const double b = 5.1 / (4 * pi * pi), c = 5 / pi, t = 1 / (8 * pi);
  const double bracket = x[1] - b * x[0] * x[0] + c * x[0] - 6;
  return bracket * bracket + 10 * (1 - t) * std::cos(x[0]) + 10;
}
constexpr double kBraninMinimum = 0.397887;

// Forrester et al. (2008) on [0, 1]: global minimum −6.020740 at x = 0.757249, a local one of
// −0.986 near x = 0.143 and a wide shoulder between.
double forrester(const Eigen::VectorXd& x) {
  const double a = 6 * x[0] - 2;
  return a * a * std::sin(12 * x[0] - 4);
}
constexpr double kForresterMinimum = -6.020740;
constexpr double kForresterArgmin = 0.757249;

BayesOptOptions box(Eigen::VectorXd lower, Eigen::VectorXd upper, uint64_t seed) {
  BayesOptOptions options;
  options.lower = std::move(lower);
  options.upper = std::move(upper);
  options.seed = seed;
  return options;
}

TEST(BayesianOptimizer, FindsTheBraninMinimumWithin40Evaluations) {
  for (uint64_t seed : {1, 2, 3}) {
    const auto result =
        bayes_minimize(branin, box(Eigen::Vector2d(-5, 0), Eigen::Vector2d(10, 15), seed), 40);
    EXPECT_LT(result.best_value, kBraninMinimum + 0.01) << "seed " << seed;
    EXPECT_EQ(result.values.size(), 40u);
  }
}

// Expected improvement keeps exploring (ξ > 0) and so refines more slowly than the confidence
// bound: 20 evaluations to 0.01 of the minimum against 15 to 0.001.
TEST(BayesianOptimizer, FindsTheGlobalMinimumOfAMultimodalFunction) {
  struct Case {
    Acquisition acquisition;
    int budget;
    double value_tolerance, point_tolerance;
  };
  for (const Case& c : {Case{Acquisition::expected_improvement, 20, 1e-2, 1e-2},
                        Case{Acquisition::upper_confidence_bound, 15, 1e-3, 5e-3}}) {
    for (uint64_t seed : {1, 2, 3, 4}) {
      BayesOptOptions options = box(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1), seed);
      options.initial_points = 3;
      options.acquisition = c.acquisition;
      const auto result = bayes_minimize(forrester, options, c.budget);
      EXPECT_LT(result.best_value, kForresterMinimum + c.value_tolerance) << "seed " << seed;
      EXPECT_NEAR(result.best_point[0], kForresterArgmin, c.point_tolerance) << "seed " << seed;
    }
  }
}

TEST(BayesianOptimizer, InitialDesignIsUniformInTheBox) {
  BayesOptOptions options = box(Eigen::Vector2d(-1, 10), Eigen::Vector2d(1, 20), 4);
  options.initial_points = 50;
  BayesianOptimizer optimizer(options);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i < 50; ++i) {
    const Eigen::VectorXd x = optimizer.ask();
    ASSERT_TRUE((x.array() >= options.lower.array()).all());
    ASSERT_TRUE((x.array() <= options.upper.array()).all());
    sum += x;
    optimizer.tell(x, x.squaredNorm());
  }
  EXPECT_NEAR(sum[0] / 50, 0.0, 0.25);
  EXPECT_NEAR(sum[1] / 50, 15.0, 1.25);
}

TEST(BayesianOptimizer, SameSeedGivesSameProposals) {
  const auto options = box(Eigen::Vector2d(-5, 0), Eigen::Vector2d(10, 15), 7);
  const auto first = bayes_minimize(branin, options, 12);
  const auto second = bayes_minimize(branin, options, 12);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(first.points[i], second.points[i]) << i;
  const auto other = bayes_minimize(branin, box(options.lower, options.upper, 8), 2);
  EXPECT_NE(first.points[0], other.points[0]);
}

// A surrogate after six evaluations of Branin, for the acquisition checks.
BayesianOptimizer six_evaluations(Acquisition acquisition) {
  BayesOptOptions options = box(Eigen::Vector2d(-5, 0), Eigen::Vector2d(10, 15), 5);
  options.acquisition = acquisition;
  BayesianOptimizer optimizer(options);
  for (int i = 0; i < 6; ++i) {
    const Eigen::VectorXd x = optimizer.ask();
    optimizer.tell(x, branin(x));
  }
  return optimizer;
}

TEST(BayesianOptimizer, AcquisitionGradientsMatchFiniteDifferences) {
  for (Acquisition acquisition :
       {Acquisition::expected_improvement, Acquisition::upper_confidence_bound}) {
    const BayesianOptimizer optimizer = six_evaluations(acquisition);
    for (const Eigen::Vector2d& point : {Eigen::Vector2d(2.0, 3.0), Eigen::Vector2d(-3.0, 12.0)}) {
      Eigen::VectorXd gradient;
      const double value = optimizer.acquisition(point, &gradient);
      EXPECT_DOUBLE_EQ(value, optimizer.acquisition(point, nullptr));
      for (int j = 0; j < 2; ++j) {
        Eigen::VectorXd plus = point, minus = point;
        plus[j] += 1e-5;
        minus[j] -= 1e-5;
        const double numeric =
            (optimizer.acquisition(plus, nullptr) - optimizer.acquisition(minus, nullptr)) / 2e-5;
        EXPECT_NEAR(gradient[j], numeric, 1e-6 * (1 + std::abs(numeric)));
      }
    }
  }
}

TEST(BayesianOptimizer, ExpectedImprovementIsTheIntegralOfTheImprovement) {
  // E[max(f_best − ξ − f, 0)] for f ~ 𝒩(μ, σ²), by the trapezoidal rule over μ ± 12σ.
  const BayesianOptimizer optimizer = six_evaluations(Acquisition::expected_improvement);
  const Eigen::Vector2d point(2.0, 3.0);
  double mean = 0, variance = 0;
  Eigen::VectorXd unused_mean_gradient, unused_variance_gradient;
  const Eigen::VectorXd unit =
      (point - optimizer.options().lower)
          .cwiseQuotient(optimizer.options().upper - optimizer.options().lower);
  optimizer.surrogate().predict(unit, mean, variance, unused_mean_gradient,
                                unused_variance_gradient);
  const double sigma = std::sqrt(variance);
  const Eigen::Map<const Eigen::VectorXd> seen(optimizer.values().data(), 6);
  const double xi = 0.01 * std::sqrt((seen.array() - seen.mean()).square().mean());
  const double threshold = optimizer.best_value() - xi;
  const int steps = 200000;
  const double low = mean - 12 * sigma, width = 24 * sigma / steps;
  double integral = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double f = low + i * width;
    const double density = std::exp(-0.5 * std::pow((f - mean) / sigma, 2)) /
                           (sigma * std::sqrt(2 * std::numbers::pi));
    const double weight = (i == 0 || i == steps) ? 0.5 : 1.0;
    integral += weight * std::max(threshold - f, 0.0) * density * width;
  }
  EXPECT_GT(integral, 1e-3);
  EXPECT_NEAR(optimizer.acquisition(point, nullptr), integral, 1e-6 * integral);
}

TEST(BayesianOptimizer, BadInputIsAnErrorNamingIt) {
  const auto message = [](auto action) { return error_message(action); };
  EXPECT_NE(message([] {
              BayesianOptimizer(box(Eigen::Vector2d(0, 0), Eigen::Vector3d(1, 1, 1), 0));
            }).find("same positive size"),
            std::string::npos);
  EXPECT_NE(message([] {
              BayesianOptimizer(box(Eigen::Vector2d(0, 2), Eigen::Vector2d(1, 1), 0));
            }).find("bounds of dimension 1 are [2, 1]"),
            std::string::npos);
  BayesianOptimizer optimizer(box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), 0));
  EXPECT_NE(message([&] {
              optimizer.tell(Eigen::Vector2d(0.5, 0.5), NAN);
            }).find("value of evaluation 0 is nan"),
            std::string::npos);
  EXPECT_NE(
      message([&] { optimizer.tell(Eigen::Vector2d(0.5, 1.5), 1.0); }).find("outside the box"),
      std::string::npos);
  EXPECT_NE(message([&] {
              optimizer.tell(Eigen::Vector3d(0.5, 0.5, 0.5), 1.0);
            }).find("point has 3 values, expected 2"),
            std::string::npos);
  EXPECT_NE(message([&] { optimizer.best_value(); }).find("no value told yet"), std::string::npos);
  EXPECT_EQ(optimizer.evaluations(), 0);
}

}  // namespace
}  // namespace tendril::adapt
