// gSDE's hand-derived log-likelihood and gradients against LibTorch autograd of the same
// expressions (SB3's StateDependentNoiseDistribution with a tanh squash, learn_features off).
#include "tendril/rl/sac/state_dependent_noise.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

namespace tendril::rl {
namespace {

torch::Tensor batch_major(const Eigen::MatrixXf& matrix) {  // features × batch → [batch, features]
  return torch::from_blob(const_cast<float*>(matrix.data()), {matrix.cols(), matrix.rows()})
      .clone();
}

torch::Tensor row_major(const Eigen::MatrixXf& matrix) {  // rows × cols → [rows, cols]
  return batch_major(matrix).t().contiguous();
}

Eigen::MatrixXf from_batch_major(const torch::Tensor& tensor) {
  const torch::Tensor contiguous = tensor.contiguous();
  Eigen::MatrixXf matrix(tensor.size(1), tensor.size(0));
  std::copy_n(contiguous.data_ptr<float>(), matrix.size(), matrix.data());
  return matrix;
}

TEST(StateDependentNoise, LogProbabilityAndGradientsMatchAutograd) {
  const int latent = 5, actions = 2, batch = 6;
  Eigen::MatrixXf raw_mean = Eigen::MatrixXf::Random(actions, batch) * 1.5f;
  raw_mean(0, 0) = 2.7f;  // clipped: no gradient
  const Eigen::MatrixXf features = Eigen::MatrixXf::Random(latent, batch).cwiseAbs();
  const Eigen::MatrixXf log_std = Eigen::MatrixXf::Random(latent, actions) * 0.5f -
                                  Eigen::MatrixXf::Constant(latent, actions, 1.0f);
  const float alpha = 0.2f;
  const Eigen::Vector2f w(0.7f, -1.3f);

  StateDependentNoiseSample sample;
  sample.standard_normal = Eigen::MatrixXf::Random(latent, actions) * 1.7f;
  sample.evaluate(raw_mean, features, log_std);
  const Eigen::MatrixXf action_gradient =
      (-2.0f / batch) * (w.asDiagonal() * sample.actions.matrix());
  Eigen::MatrixXf mean_gradient;
  Eigen::MatrixXf log_std_gradient = Eigen::MatrixXf::Zero(latent, actions);
  sample.gradients(raw_mean, features, log_std, action_gradient, alpha, mean_gradient,
                   log_std_gradient);

  torch::Tensor raw_mean_t = batch_major(raw_mean).requires_grad_(true);  // [B, A]
  torch::Tensor log_std_t = row_major(log_std).requires_grad_(true);      // [L, A]
  const torch::Tensor z = batch_major(features);                          // [B, L], constant
  const torch::Tensor e = row_major(sample.standard_normal);
  const torch::Tensor mean = torch::clamp(raw_mean_t, -2.0, 2.0);
  const torch::Tensor sigma = torch::exp(log_std_t);
  const torch::Tensor u = mean + torch::mm(z, sigma * e);
  const torch::Tensor s = torch::sqrt(torch::mm(z.pow(2), sigma.pow(2)) + 1e-6);
  const torch::Tensor a = torch::tanh(u);
  const torch::Tensor gaussian =
      -(u - mean).pow(2) / (2 * s.pow(2)) - torch::log(s) - 0.5 * std::log(2 * M_PI);
  const torch::Tensor log_prob = (gaussian - torch::log(1 - a.pow(2) + 1e-6)).sum(1);
  const torch::Tensor loss =
      (alpha * log_prob).mean() - (a.pow(2) * torch::tensor({0.7f, -1.3f})).sum(1).mean();
  loss.backward();

  EXPECT_TRUE(sample.actions.isApprox(from_batch_major(a.detach()), 1e-5f));
  for (int i = 0; i < batch; ++i)
    EXPECT_NEAR(sample.log_probs[i], log_prob[i].item<float>(), 1e-4f);
  EXPECT_TRUE(mean_gradient.isApprox(from_batch_major(raw_mean_t.grad()), 1e-4f))
      << mean_gradient << "\n\n"
      << from_batch_major(raw_mean_t.grad());
  EXPECT_EQ(mean_gradient(0, 0), 0.0f);
  const Eigen::MatrixXf expected = from_batch_major(log_std_t.grad().t());
  EXPECT_TRUE(log_std_gradient.isApprox(expected, 1e-4f)) << log_std_gradient << "\n\n" << expected;
}

}  // namespace
}  // namespace tendril::rl
