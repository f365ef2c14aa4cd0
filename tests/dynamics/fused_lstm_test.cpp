#include "tendril/dynamics/fused_lstm.hpp"

#include <gtest/gtest.h>

namespace tendril::dynamics {
namespace {

// The hand-written passes against LibTorch's LSTM and its autograd (the oracle): outputs, final
// states and the gradients of every input, initial state and parameter for a loss that weighs
// all three outputs.
TEST(FusedLstm, ForwardAndGradientsMatchLibTorchsLstm) {
  torch::manual_seed(3);
  const int64_t batch = 4, steps = 7, features = 3, hidden = 5, layers = 2;
  torch::nn::LSTM lstm(
      torch::nn::LSTMOptions(features, hidden).num_layers(layers).batch_first(true));
  const torch::Tensor input = torch::randn({batch, steps, features});
  const torch::Tensor h0 = torch::randn({layers, batch, hidden});
  const torch::Tensor c0 = torch::randn({layers, batch, hidden});
  const torch::Tensor weigh_out = torch::randn({batch, steps, hidden});
  const torch::Tensor weigh_h = torch::randn({layers, batch, hidden});
  const torch::Tensor weigh_c = torch::randn({layers, batch, hidden});

  auto run = [&](bool fused) {
    const torch::Tensor x = input.clone().requires_grad_(true);
    const torch::Tensor h = h0.clone().requires_grad_(true);
    const torch::Tensor c = c0.clone().requires_grad_(true);
    for (auto& parameter : lstm->parameters()) parameter.mutable_grad() = torch::Tensor();
    torch::Tensor out, h_n, c_n;
    if (fused) {
      std::tie(out, h_n, c_n) = fused_lstm(lstm, x, h, c);
    } else {
      auto [o, state] = lstm->forward(x, std::make_tuple(h, c));
      out = o;
      std::tie(h_n, c_n) = state;
    }
    const torch::Tensor loss =
        (out * weigh_out).sum() + (h_n * weigh_h).sum() + (c_n * weigh_c).sum();
    loss.backward();
    std::vector<torch::Tensor> results{out.detach(), h_n.detach(), c_n.detach(),
                                       x.grad(),     h.grad(),     c.grad()};
    for (const auto& parameter : lstm->parameters()) results.push_back(parameter.grad().clone());
    return results;
  };
  const auto reference = run(false);
  const auto fused = run(true);
  ASSERT_EQ(reference.size(), fused.size());
  const char* names[] = {"output", "h_n", "c_n", "d input", "d h0", "d c0"};
  for (std::size_t i = 0; i < reference.size(); ++i) {
    SCOPED_TRACE(i < 6 ? names[i] : "d parameter " + std::to_string(i - 6));
    ASSERT_EQ(reference[i].sizes(), fused[i].sizes());
    const double scale = reference[i].abs().max().item<double>();
    EXPECT_LT((reference[i] - fused[i]).abs().max().item<double>(), 1e-5 * (1.0 + scale));
  }
}

TEST(FusedLstm, ZeroInitialStatesAndUnusedOutputs) {
  torch::manual_seed(4);
  torch::nn::LSTM lstm(torch::nn::LSTMOptions(2, 3).num_layers(1).batch_first(true));
  const torch::Tensor input = torch::randn({2, 5, 2});
  const auto [out, h_n, c_n] = fused_lstm(lstm, input);
  const auto [reference, state] = lstm->forward(input);
  EXPECT_TRUE(torch::allclose(out, reference, 1e-5, 1e-6));
  EXPECT_TRUE(torch::allclose(c_n, std::get<1>(state), 1e-5, 1e-6));
  // Only the last step's output feeds the loss (the dynamics networks' head).
  const torch::Tensor x = input.clone().requires_grad_(true);
  std::get<0>(fused_lstm(lstm, x)).select(1, 4).sum().backward();
  const torch::Tensor fused_grad = x.grad().clone();
  x.mutable_grad() = torch::Tensor();
  std::get<0>(lstm->forward(x)).select(1, 4).sum().backward();
  EXPECT_TRUE(torch::allclose(fused_grad, x.grad(), 1e-5, 1e-6));
}

// Without gradients (evaluation, prediction) the pass keeps only what the next step needs and
// computes the same numbers.
TEST(FusedLstm, ForwardWithoutGradientsIsTheSame) {
  torch::manual_seed(5);
  torch::nn::LSTM lstm(torch::nn::LSTMOptions(3, 4).num_layers(2).batch_first(true));
  const torch::Tensor input = torch::randn({3, 6, 3});
  const auto [out, h_n, c_n] = fused_lstm(lstm, input);
  ASSERT_TRUE(out.requires_grad());
  torch::NoGradGuard no_grad;
  const auto [plain_out, plain_h, plain_c] = fused_lstm(lstm, input);
  EXPECT_FALSE(plain_out.requires_grad());
  EXPECT_TRUE(torch::equal(out.detach(), plain_out));
  EXPECT_TRUE(torch::equal(h_n.detach(), plain_h));
  EXPECT_TRUE(torch::equal(c_n.detach(), plain_c));
}

}  // namespace
}  // namespace tendril::dynamics
