#include "tendril/dynamics/softsign_lstm_network.hpp"

#include <gtest/gtest.h>

#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

double softsign(double v) { return v / (1.0 + std::abs(v)); }
double sigmoid(double v) { return 1.0 / (1.0 + std::exp(-v)); }

ArchitectureSpec seed002_spec() {
  ArchitectureSpec spec = testing::small_description(Architecture::kSoftsignLstm).architecture;
  spec.hidden_size = 6;
  return spec;
}

// Seed 002's network by hand for one sample: one step from zero state, so
//   c = σ(i) s(g),  h = σ(o) s(c),  y = s(W h + b)   with [i, f, g, o] = W_ih v + b_lstm.
TEST(SoftsignLstmNetwork, ForwardIsTheKerasSoftsignLstmByHand) {
  SoftsignLstmNetwork network(seed002_spec());
  Rng rng(3);
  network.initialize(rng);
  network.eval();
  const torch::Tensor input = torch::randn({1, 1, 14});
  const torch::Tensor output = network.forward(input);
  const auto parameters = network.named_parameters();
  const torch::Tensor w_ih = parameters["weight_ih"], bias = parameters["bias"];
  const torch::Tensor w = parameters["head.weight"], b = parameters["head.bias"];
  const int h = 6;
  std::vector<double> hidden(h);
  for (int k = 0; k < h; ++k) {
    double gate[4];
    for (int q = 0; q < 4; ++q) {
      gate[q] = bias[q * h + k].item<double>();
      for (int j = 0; j < 14; ++j) {
        gate[q] += w_ih[q * h + k][j].item<double>() * input[0][0][j].item<double>();
      }
    }
    const double cell = sigmoid(gate[0]) * softsign(gate[2]);
    hidden[k] = sigmoid(gate[3]) * softsign(cell);
  }
  for (int s = 0; s < 4; ++s) {
    double y = b[s].item<double>();
    for (int k = 0; k < h; ++k) y += w[s][k].item<double>() * hidden[k];
    EXPECT_NEAR(output[0][s].item<double>(), softsign(y), 1e-6);
  }
}

TEST(SoftsignLstmNetwork, KerasInitialisationAndDropoutInTrainingOnly) {
  SoftsignLstmNetwork network(seed002_spec());
  Rng rng(4);
  network.initialize(rng);
  const auto parameters = network.named_parameters();
  // Unit forget bias, zero elsewhere; an orthogonal recurrent kernel (columns orthonormal).
  const torch::Tensor bias = parameters["bias"];
  EXPECT_TRUE(torch::equal(bias.narrow(0, 6, 6), torch::ones({6})));
  EXPECT_EQ(bias.abs().sum().item<double>(), 6.0);
  const torch::Tensor w_hh = parameters["weight_hh"];  // [4H, H]
  EXPECT_TRUE(torch::allclose(w_hh.t().mm(w_hh), torch::eye(6), 1e-5, 1e-5));

  const torch::Tensor input = torch::randn({500, 1, 14});
  network.eval();
  const torch::Tensor a = network.forward(input), b = network.forward(input);
  EXPECT_TRUE(torch::equal(a, b));
  network.train();
  network.set_noise(Rng(9));
  const torch::Tensor dropped = network.forward(input);
  EXPECT_FALSE(torch::equal(a, dropped));
}

}  // namespace
}  // namespace tendril::dynamics
