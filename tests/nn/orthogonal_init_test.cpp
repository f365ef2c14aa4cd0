#include "tendril/nn/orthogonal_init.hpp"

#include <gtest/gtest.h>

#include "tendril/nn/mlp.hpp"

namespace tendril::nn {
namespace {

// W Wᵀ (wide or square) or Wᵀ W (tall) must equal gain² I.
void expect_scaled_orthogonal(const torch::Tensor& weight, double gain) {
  const bool tall = weight.size(0) > weight.size(1);
  const torch::Tensor gram = tall ? weight.t().mm(weight) : weight.mm(weight.t());
  const torch::Tensor expected = gain * gain * torch::eye(gram.size(0));
  EXPECT_TRUE(torch::allclose(gram, expected, 1e-5, 1e-5)) << gram;
}

TEST(OrthogonalInit, TallWideAndSquareWeightsAreScaledOrthogonal) {
  Rng rng(7);
  for (auto [out, in] : {std::pair{64, 3}, std::pair{2, 64}, std::pair{64, 64}}) {
    torch::nn::Linear layer(in, out);
    orthogonal_init(layer, kHiddenGain, rng);
    expect_scaled_orthogonal(layer->weight, kHiddenGain);
    EXPECT_EQ(layer->bias.abs().max().item<float>(), 0.0f);
  }
}

TEST(OrthogonalInit, SameSeedSameWeightsDifferentSeedDifferent) {
  Rng a(3), b(3), c(4);
  torch::nn::Linear la(5, 8), lb(5, 8), lc(5, 8);
  orthogonal_init(la, 1.0, a);
  orthogonal_init(lb, 1.0, b);
  orthogonal_init(lc, 1.0, c);
  EXPECT_TRUE(torch::equal(la->weight, lb->weight));
  EXPECT_FALSE(torch::equal(la->weight, lc->weight));
}

TEST(Mlp, TrunkShapesAndActivations) {
  Rng rng(1);
  Mlp tanh_trunk(3, std::vector<int64_t>{16, 8}, Activation::kTanh, true, rng);
  EXPECT_EQ(tanh_trunk->output_size(), 8);
  EXPECT_EQ(tanh_trunk->layers().size(), 2u);
  const torch::Tensor x = torch::randn({5, 3}) * 100.0;
  const torch::Tensor y = tanh_trunk->forward(x);
  EXPECT_EQ(y.sizes(), (std::vector<int64_t>{5, 8}));
  EXPECT_LE(y.abs().max().item<float>(), 1.0f);

  Mlp relu_trunk(3, std::vector<int64_t>{16}, Activation::kRelu, true, rng);
  EXPECT_GE(relu_trunk->forward(x).min().item<float>(), 0.0f);

  Mlp identity(3, std::vector<int64_t>{}, Activation::kTanh, true, rng);
  EXPECT_EQ(identity->output_size(), 3);
  EXPECT_TRUE(torch::equal(identity->forward(x), x));
}

}  // namespace
}  // namespace tendril::nn
