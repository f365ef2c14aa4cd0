// The hand-written layer normalisation against torch.nn.functional.layer_norm and its autograd.
#include "tendril/nn/layer_norm.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include "support/torch_networks.hpp"

namespace tendril::nn {
namespace {

TEST(LayerNorm, ForwardAndBackwardMatchTorch) {
  const Eigen::MatrixXf inputs = 3.0f * Eigen::MatrixXf::Random(6, 9);
  const Eigen::MatrixXf output_gradient = Eigen::MatrixXf::Random(6, 9);
  const LayerNorm norm;
  LayerNorm::Tape tape;
  norm.forward(inputs, tape);
  Eigen::MatrixXf input_gradient;
  norm.backward(tape, output_gradient, input_gradient);

  torch::Tensor x = testing::rows_of(inputs).requires_grad_(true);  // [batch, features]
  const torch::Tensor y = torch::layer_norm(x, {6}, {}, {}, 1e-5);
  (y * testing::rows_of(output_gradient)).sum().backward();
  EXPECT_LT((tape.output - testing::columns_of(y)).cwiseAbs().maxCoeff(), 1e-5f);
  EXPECT_LT((input_gradient - testing::columns_of(x.grad())).cwiseAbs().maxCoeff(), 1e-5f);
  // Each column has mean 0 and variance var / (var + ε) ≈ 1.
  for (Eigen::Index i = 0; i < 9; ++i) {
    EXPECT_NEAR(tape.output.col(i).mean(), 0.0f, 1e-6f);
    EXPECT_NEAR(tape.output.col(i).squaredNorm() / 6.0f, 1.0f, 1e-4f);
  }
}

TEST(LayerNorm, AConstantColumnStaysFinite) {
  const LayerNorm norm;
  LayerNorm::Tape tape;
  norm.forward(Eigen::MatrixXf::Constant(4, 2, 7.0f), tape);
  EXPECT_TRUE(tape.output.allFinite());
  EXPECT_EQ(tape.output.cwiseAbs().maxCoeff(), 0.0f);
}

}  // namespace
}  // namespace tendril::nn
