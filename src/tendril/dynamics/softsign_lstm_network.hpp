#pragma once

#include "tendril/dynamics/sequence_network.hpp"

namespace tendril::dynamics {

// Seed 002's model (§III-C, eq. (1)): one LSTM layer whose cell and output activations are
// softsign, s(v) = v / (1 + |v|), with sigmoid gates (Keras' LSTM(activation="softsign")):
//   [i, f, g, o] = W_ih v_k + W_hh h_{k−1} + b,
//   c_k = σ(f) ⊙ c_{k−1} + σ(i) ⊙ s(g),   h_k = σ(o) ⊙ s(c_k),
// then dropout on the last h (training only, masks from the network's own stream) and a dense
// softsign output: x_{t+1} normalised to [−1, 1]. The input is one step of the 45 = 2·9 + 3·9
// values (x_t, x_{t−1}, τ_t, τ_{t−1}, τ_{t−2}) (Sec. IV-A1's input dimension), zero initial state.
class SoftsignLstmNetwork : public SequenceNetwork {
 public:
  explicit SoftsignLstmNetwork(const ArchitectureSpec& spec);

  torch::Tensor forward(const torch::Tensor& inputs) override;
  void initialize(Rng& rng) override;

 private:
  torch::Tensor weight_ih_, weight_hh_, bias_;
  torch::nn::Linear head_{nullptr};
};

}  // namespace tendril::dynamics
