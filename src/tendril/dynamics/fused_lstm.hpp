#pragma once

#include <torch/torch.h>

#include <tuple>

namespace tendril::dynamics {

// A multi-layer LSTM over a batch of sequences with its forward and backward passes written out
// (one autograd node for the whole stack), computing what torch::nn::LSTM computes with the same
// parameters (PyTorch's gate order i, f, g, o; Hochreiter & Schmidhuber 1997):
//   [i, f, g, o] = W_ih x_t + b_ih + W_hh h_{t−1} + b_hh
//   c_t = σ(f) ⊙ c_{t−1} + σ(i) ⊙ tanh(g),   h_t = σ(o) ⊙ tanh(c_t)
// The input projections of a layer are one matrix product over all steps; the weight gradients
// one product over all steps in the backward pass; each step costs one product and one pass
// over its gates. `lstm` must be batch-first and unidirectional, with biases.
//
// input [B, T, F]; h0, c0 [L, B, H] or undefined (zeros). Returns the last layer's outputs
// [B, T, H] and the final states h_n, c_n [L, B, H].
std::tuple<torch::Tensor, torch::Tensor, torch::Tensor> fused_lstm(const torch::nn::LSTM& lstm,
                                                                   const torch::Tensor& input,
                                                                   const torch::Tensor& h0 = {},
                                                                   const torch::Tensor& c0 = {});

}  // namespace tendril::dynamics
