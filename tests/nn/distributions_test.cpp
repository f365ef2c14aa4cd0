#include <gtest/gtest.h>

#include <cmath>

#include "tendril/nn/categorical.hpp"
#include "tendril/nn/diag_gaussian.hpp"

namespace tendril::nn {
namespace {

TEST(DiagGaussian, LogProbEntropyAndKlMatchClosedForms) {
  // One sample, two dimensions: μ = (0, 1), σ = (1, 2), a = (1, 1).
  const torch::Tensor mean = torch::tensor({{0.0f, 1.0f}});
  const torch::Tensor log_std = torch::tensor({0.0f, std::log(2.0f)});
  const torch::Tensor action = torch::tensor({{1.0f, 1.0f}});
  const double expected_log_prob =
      -0.5 * 1.0 - 0.5 * std::log(2 * M_PI) + (-std::log(2.0) - 0.5 * std::log(2 * M_PI));
  EXPECT_NEAR(diag_gaussian::log_prob(mean, log_std, action).item<double>(), expected_log_prob,
              1e-5);
  const double expected_entropy = 2 * (0.5 + 0.5 * std::log(2 * M_PI)) + std::log(2.0);
  EXPECT_NEAR(diag_gaussian::entropy(mean, log_std).item<double>(), expected_entropy, 1e-5);

  // KL(N(0,1) ‖ N(1,2²)) = log 2 + (1 + 1)/8 − ½, plus 0 for the identical second dimension.
  const torch::Tensor mean_q = torch::tensor({{1.0f, 1.0f}});
  const torch::Tensor log_std_q = torch::tensor({std::log(2.0f), std::log(2.0f)});
  EXPECT_NEAR(diag_gaussian::kl(mean, log_std, mean_q, log_std_q).item<double>(),
              std::log(2.0) + 2.0 / 8.0 - 0.5, 1e-5);
  EXPECT_NEAR(diag_gaussian::kl(mean, log_std, mean, log_std).item<double>(), 0.0, 1e-7);
}

TEST(Categorical, LogProbEntropyAndKlMatchClosedForms) {
  // p = (½, ¼, ¼) from logits log p (+ a constant, which must not matter).
  const torch::Tensor logits = torch::log(torch::tensor({{0.5f, 0.25f, 0.25f}})) + 3.0f;
  EXPECT_NEAR(categorical::log_prob(logits, torch::tensor({{1.0f}})).item<double>(), std::log(0.25),
              1e-6);
  EXPECT_NEAR(categorical::entropy(logits).item<double>(),
              -(0.5 * std::log(0.5) + 0.5 * std::log(0.25)), 1e-6);
  const torch::Tensor uniform = torch::zeros({1, 3});
  EXPECT_NEAR(categorical::kl(logits, uniform).item<double>(),
              0.5 * std::log(0.5 * 3) + 0.5 * std::log(0.25 * 3), 1e-6);
  EXPECT_NEAR(categorical::kl(logits, logits).item<double>(), 0.0, 1e-7);
}

TEST(Categorical, BatchedIndicesGatherPerRow) {
  const torch::Tensor logits = torch::tensor({{0.0f, 10.0f}, {10.0f, 0.0f}});
  const torch::Tensor log_p = categorical::log_prob(logits, torch::tensor({{1.0f}, {0.0f}}));
  EXPECT_EQ(log_p.sizes(), (std::vector<int64_t>{2}));
  EXPECT_NEAR(log_p[0].item<double>(), log_p[1].item<double>(), 1e-7);
  EXPECT_GT(log_p[0].item<double>(), -1e-3);
}

}  // namespace
}  // namespace tendril::nn
