#pragma once

#include "tendril/dynamics/sequence_network.hpp"

namespace tendril::dynamics {

// Seed 001's vanilla RNN and LSTM (thesis §4.2.4): L recurrent layers over the window, a linear
// head on the last step's output, Δx = bound · tanh(head).
class RecurrentNetwork : public SequenceNetwork {
 public:
  explicit RecurrentNetwork(const ArchitectureSpec& spec);

  torch::Tensor forward(const torch::Tensor& inputs) override;
  void initialize(Rng& rng) override;

 private:
  torch::nn::RNN rnn_{nullptr};
  torch::nn::LSTM lstm_{nullptr};
  torch::nn::Linear head_{nullptr};
};

}  // namespace tendril::dynamics
