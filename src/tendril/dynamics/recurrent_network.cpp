#include "tendril/dynamics/recurrent_network.hpp"

#include "tendril/dynamics/fused_lstm.hpp"
#include "tendril/dynamics/parameter_init.hpp"

namespace tendril::dynamics {

RecurrentNetwork::RecurrentNetwork(const ArchitectureSpec& spec) : SequenceNetwork(spec) {
  if (spec.kind == Architecture::kRnn) {
    rnn_ = register_module(
        "rnn", torch::nn::RNN(torch::nn::RNNOptions(spec.feature_size(), spec.hidden_size)
                                  .num_layers(spec.layers)
                                  .nonlinearity(torch::kTanh)
                                  .batch_first(true)));
  } else {
    lstm_ = register_module(
        "lstm", torch::nn::LSTM(torch::nn::LSTMOptions(spec.feature_size(), spec.hidden_size)
                                    .num_layers(spec.layers)
                                    .batch_first(true)));
  }
  head_ = register_module("head", torch::nn::Linear(spec.hidden_size, spec.state_dim));
}

torch::Tensor RecurrentNetwork::forward(const torch::Tensor& inputs) {
  const torch::Tensor outputs =
      rnn_ ? std::get<0>(rnn_->forward(inputs)) : std::get<0>(fused_lstm(lstm_, inputs));
  const torch::Tensor last = outputs.select(1, outputs.size(1) - 1);
  return torch::tanh(head_->forward(last)) * spec_.output_bound;
}

void RecurrentNetwork::initialize(Rng& rng) {
  if (rnn_) {
    init_recurrent(*rnn_, spec_.hidden_size, rng);
  } else {
    init_recurrent(*lstm_, spec_.hidden_size, rng);
  }
  init_linear(head_, rng);
}

}  // namespace tendril::dynamics
