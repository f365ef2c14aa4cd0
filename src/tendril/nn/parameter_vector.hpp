#pragma once

#include <torch/torch.h>

#include <vector>

namespace tendril::nn {

// Flat views of a parameter list, for second-order methods (TRPO's conjugate gradient works
// on one vector θ). Order is the list's order.

// All parameters concatenated into one detached 1-D tensor.
torch::Tensor flatten_parameters(const std::vector<torch::Tensor>& parameters);
// Gradients as one 1-D tensor (zeros for parameters without a gradient).
torch::Tensor flatten_gradients(const std::vector<torch::Tensor>& parameters);
// Tensors (e.g. from torch::autograd::grad) concatenated into one 1-D tensor.
torch::Tensor flatten(const std::vector<torch::Tensor>& tensors);
// Writes consecutive slices of `flat` into the parameters (without recording gradients).
void assign_parameters(const std::vector<torch::Tensor>& parameters, const torch::Tensor& flat);

}  // namespace tendril::nn
