#include "tendril/dynamics/softsign_lstm_network.hpp"

#include <vector>

#include "tendril/dynamics/parameter_init.hpp"

namespace tendril::dynamics {

SoftsignLstmNetwork::SoftsignLstmNetwork(const ArchitectureSpec& spec) : SequenceNetwork(spec) {
  const int64_t h = spec.hidden_size;
  weight_ih_ = register_parameter("weight_ih", torch::zeros({4 * h, spec.feature_size()}));
  weight_hh_ = register_parameter("weight_hh", torch::zeros({4 * h, h}));
  bias_ = register_parameter("bias", torch::zeros({4 * h}));
  head_ = register_module("head", torch::nn::Linear(h, spec.state_dim));
}

torch::Tensor SoftsignLstmNetwork::forward(const torch::Tensor& inputs) {
  namespace F = torch::nn::functional;
  const int64_t batch = inputs.size(0), h = spec_.hidden_size;
  torch::Tensor hidden = torch::zeros({batch, h});
  torch::Tensor cell = torch::zeros({batch, h});
  for (int64_t k = 0; k < inputs.size(1); ++k) {
    const torch::Tensor gates =
        torch::addmm(bias_, inputs.select(1, k), weight_ih_.t()) + hidden.matmul(weight_hh_.t());
    const auto parts = gates.chunk(4, 1);  // Keras' order: input, forget, cell, output
    cell = torch::sigmoid(parts[1]) * cell + torch::sigmoid(parts[0]) * F::softsign(parts[2]);
    hidden = torch::sigmoid(parts[3]) * F::softsign(cell);
  }
  if (is_training() && spec_.dropout > 0.0) {
    const double keep = 1.0 - spec_.dropout;
    std::vector<float> mask(static_cast<std::size_t>(batch * h));
    for (float& m : mask) m = noise_.uniform() < keep ? static_cast<float>(1.0 / keep) : 0.0f;
    hidden = hidden * torch::from_blob(mask.data(), {batch, h}, torch::kFloat).clone();
  }
  return F::softsign(head_->forward(hidden));
}

void SoftsignLstmNetwork::initialize(Rng& rng) {
  // Keras' defaults: Glorot-uniform kernel, orthogonal recurrent kernel, zero bias with the
  // forget gate's set to 1 (unit_forget_bias); Glorot-uniform dense kernel, zero bias.
  const int64_t h = spec_.hidden_size;
  fill_glorot_uniform(weight_ih_, spec_.feature_size(), 4 * h, rng);
  fill_orthogonal(weight_hh_, rng);
  fill_constant(bias_, 0.0);
  {
    torch::NoGradGuard no_grad;
    bias_.narrow(0, h, h).fill_(1.0);
  }
  fill_glorot_uniform(head_->weight, h, spec_.state_dim, rng);
  fill_constant(head_->bias, 0.0);
}

}  // namespace tendril::dynamics
