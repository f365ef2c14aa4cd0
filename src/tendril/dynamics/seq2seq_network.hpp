#pragma once

#include "tendril/dynamics/sequence_network.hpp"

namespace tendril::dynamics {

// Seed 001's Seq2Seq, with or without attention (thesis §4.2.4, Fig. 4.3; Sutskever et al. 2014,
// Luong et al. 2015). An L-layer LSTM encoder reads the window; an L-layer LSTM decoder,
// started from the encoder's final (h, c), reads one step: the newest row [x_t, u_t] — or, with
// attention, that row projected to the hidden size, attended by multi-head dot-product
// attention over all encoder outputs (query: the projection; keys and values: the outputs) and
// projected back to the row size. A linear head on the decoder output gives
// Δx = bound · tanh(head).
class Seq2SeqNetwork : public SequenceNetwork {
 public:
  explicit Seq2SeqNetwork(const ArchitectureSpec& spec);

  torch::Tensor forward(const torch::Tensor& inputs) override;
  void initialize(Rng& rng) override;

 private:
  torch::nn::LSTM encoder_{nullptr};
  torch::nn::LSTM decoder_{nullptr};
  torch::nn::Linear query_{nullptr};
  torch::nn::MultiheadAttention attention_{nullptr};
  torch::nn::Linear back_{nullptr};
  torch::nn::Linear head_{nullptr};
};

}  // namespace tendril::dynamics
