#pragma once

#include <torch/torch.h>

#include "tendril/core/rng.hpp"

namespace tendril::dynamics {

// Initial weights drawn from tendril's own random streams (not LibTorch's global generator),
// so a seed fixes a model exactly. The distributions are those of the libraries the seeds used.

// U(−bound, bound) in every entry.
void fill_uniform(torch::Tensor& parameter, double bound, Rng& rng);
// Glorot/Xavier uniform: bound √(6 / (fan_in + fan_out)).
void fill_glorot_uniform(torch::Tensor& parameter, int64_t fan_in, int64_t fan_out, Rng& rng);
// A (rows × columns) matrix with orthonormal columns (rows ≥ columns) or rows (Keras'
// Orthogonal: QR of a standard normal matrix, signs fixed by R's diagonal).
void fill_orthogonal(torch::Tensor& parameter, Rng& rng);
void fill_constant(torch::Tensor& parameter, double value);

// PyTorch's default for RNN, LSTM and Linear layers: every weight and bias U(±1/√fan_in)
// (fan_in = hidden size for recurrent layers, input size for Linear).
void init_recurrent(torch::nn::Module& layer, int64_t hidden_size, Rng& rng);
void init_linear(torch::nn::Linear& layer, Rng& rng);

}  // namespace tendril::dynamics
