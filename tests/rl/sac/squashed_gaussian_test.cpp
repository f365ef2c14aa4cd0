// SAC's hand-derived policy log-likelihood and actor-loss gradient against LibTorch autograd of
// the same expressions (SB3's SquashedDiagGaussianDistribution).
#include "tendril/rl/sac/squashed_gaussian.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

namespace tendril::rl {
namespace {

torch::Tensor to_tensor(const Eigen::MatrixXf& matrix) {
  // (rows × cols) column-major is (cols × rows) row-major.
  return torch::from_blob(const_cast<float*>(matrix.data()), {matrix.cols(), matrix.rows()})
      .clone();
}

Eigen::MatrixXf to_matrix(
    const torch::Tensor& batch_major) {  // [batch, features] → features × batch
  const torch::Tensor contiguous = batch_major.contiguous();
  Eigen::MatrixXf matrix(batch_major.size(1), batch_major.size(0));
  std::copy_n(contiguous.data_ptr<float>(), matrix.size(), matrix.data());
  return matrix;
}

TEST(SquashedGaussian, LogProbabilityAndGradientMatchAutograd) {
  const int actions = 3, batch = 7;
  Eigen::MatrixXf head = Eigen::MatrixXf::Random(2 * actions, batch);
  head(actions, 0) = 2.5f;  // log σ above the clamp: no gradient
  head(actions + 1, 1) = -1.2f;
  Eigen::MatrixXf noise = Eigen::MatrixXf::Random(actions, batch) * 1.5f;
  const float alpha = 0.37f;
  // An outside term −mean_b Σ_j w_j a_j² standing in for −min Q: ∂/∂a = −2 w a / B.
  const Eigen::Vector3f w(0.5f, -1.0f, 2.0f);

  SquashedGaussianSample sample;
  sample.noise = noise;
  sample.evaluate(head);
  const Eigen::MatrixXf action_gradient =
      (-2.0f / batch) * (w.asDiagonal() * sample.actions.matrix());
  Eigen::MatrixXf gradient;
  sample.head_gradient(head, action_gradient, alpha, gradient);

  torch::Tensor head_t = to_tensor(head).requires_grad_(true);  // [batch, 2A]
  const torch::Tensor eps = to_tensor(noise);
  const torch::Tensor mean = head_t.slice(1, 0, actions);
  const torch::Tensor log_std = torch::clamp(head_t.slice(1, actions, 2 * actions), -20.0, 2.0);
  const torch::Tensor std = torch::exp(log_std);
  const torch::Tensor u = mean + std * eps;
  const torch::Tensor a = torch::tanh(u);
  const torch::Tensor gaussian =
      -(u - mean).pow(2) / (2 * std.pow(2)) - log_std - 0.5 * std::log(2 * M_PI);
  const torch::Tensor log_prob = (gaussian - torch::log(1 - a.pow(2) + 1e-6)).sum(1);
  const torch::Tensor w_t = torch::tensor({0.5f, -1.0f, 2.0f});
  const torch::Tensor loss = (alpha * log_prob).mean() - (a.pow(2) * w_t).sum(1).mean();
  loss.backward();

  EXPECT_TRUE(sample.actions.isApprox(to_matrix(a.detach()), 1e-5f));
  for (int i = 0; i < batch; ++i) {
    EXPECT_NEAR(sample.log_probs[i], log_prob[i].item<float>(), 1e-4f) << i;
  }
  const Eigen::MatrixXf expected = to_matrix(head_t.grad());
  EXPECT_TRUE(gradient.isApprox(expected, 1e-4f)) << gradient << "\n\n" << expected;
  EXPECT_EQ(gradient(actions, 0), 0.0f);
}

}  // namespace
}  // namespace tendril::rl
