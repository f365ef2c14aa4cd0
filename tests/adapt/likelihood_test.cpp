#include "tendril/adapt/likelihood.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tendril/core/rng.hpp"

namespace tendril::adapt {
namespace {

struct Problem {
  Eigen::MatrixXd inputs, residuals;
  Eigen::VectorXd theta;
};

Problem problem(int n, int d, int outputs, uint64_t seed) {
  Rng rng(seed);
  Problem p{Eigen::MatrixXd(n, d), Eigen::MatrixXd(n, outputs), Eigen::VectorXd(d + 2)};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < d; ++j) p.inputs(i, j) = rng.uniform(-1.0, 1.0);
    for (int k = 0; k < outputs; ++k) {
      p.residuals(i, k) = std::cos((k + 1) * p.inputs(i, 0)) + 0.1 * rng.normal();
    }
  }
  for (int j = 0; j < d; ++j) p.theta[j] = std::log(0.4 + 0.3 * j);
  p.theta[d] = std::log(0.8);
  p.theta[d + 1] = std::log(0.05);
  return p;
}

class BothKernels : public ::testing::TestWithParam<KernelType> {};
INSTANTIATE_TEST_SUITE_P(Kernels, BothKernels,
                         ::testing::Values(KernelType::squared_exponential, KernelType::matern52),
                         [](const auto& info) { return kernel_type_name(info.param); });

// Sizes across the 64-row blocks of the inverse, so the blocked paths are exercised.
TEST_P(BothKernels, SeveralOutputsSumTheirLikelihoodsAndGradients) {
  const Problem p = problem(150, 3, 3, 1);
  LikelihoodWorkspace workspace;
  Eigen::VectorXd joint_gradient, gradient, summed_gradient = Eigen::VectorXd::Zero(5);
  const double joint = log_marginal_likelihood(GetParam(), p.inputs, p.residuals, p.theta,
                                               &joint_gradient, workspace);
  double summed = 0.0;
  for (int k = 0; k < 3; ++k) {
    summed += log_marginal_likelihood(GetParam(), p.inputs, p.residuals.col(k), p.theta, &gradient,
                                      workspace);
    summed_gradient += gradient;
  }
  EXPECT_NEAR(joint, summed, 1e-9 * std::abs(summed));
  EXPECT_LT((joint_gradient - summed_gradient).cwiseAbs().maxCoeff(),
            1e-9 * summed_gradient.cwiseAbs().maxCoeff());
}

TEST_P(BothKernels, GradientOfSeveralOutputsMatchesFiniteDifferences) {
  const Problem p = problem(90, 4, 2, 2);
  LikelihoodWorkspace workspace;
  Eigen::VectorXd gradient;
  log_marginal_likelihood(GetParam(), p.inputs, p.residuals, p.theta, &gradient, workspace);
  for (int j = 0; j < p.theta.size(); ++j) {
    Eigen::VectorXd plus = p.theta, minus = p.theta;
    plus[j] += 1e-5;
    minus[j] -= 1e-5;
    const double numeric =
        (log_marginal_likelihood(GetParam(), p.inputs, p.residuals, plus, nullptr, workspace) -
         log_marginal_likelihood(GetParam(), p.inputs, p.residuals, minus, nullptr, workspace)) /
        2e-5;
    EXPECT_NEAR(gradient[j], numeric, 1e-6 * (1 + std::abs(numeric))) << "parameter " << j;
  }
}

}  // namespace
}  // namespace tendril::adapt
