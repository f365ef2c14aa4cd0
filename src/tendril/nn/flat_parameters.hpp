#pragma once

#include <torch/torch.h>

#include <cstdint>
#include <vector>

namespace tendril::nn {

// A list of parameters whose values live in one contiguous float buffer and whose gradients
// live in another: each parameter (and its `.grad()`) becomes a view of its slice, in list
// order. Optimizer steps and gradient-norm clipping then run as a few whole-buffer operations
// instead of a loop of small ones per parameter, which is what a small control network's
// update costs (per-call overhead, not arithmetic).
//
// Invariants: the parameters keep their identity (module->parameters() returns the same
// tensors, now viewing `values()`); autograd accumulates into the gradient views in place, so
// `gradients()` holds the gradient of everything back-propagated since `zero_grad`. Replacing a
// parameter's data elsewhere (`set_data`, `set_`) breaks the link.
class FlatParameters {
 public:
  // Copies the values of `parameters` (float, on the CPU) into the flat buffer and makes each
  // parameter and its gradient a view of it. Gradients start at zero.
  explicit FlatParameters(std::vector<torch::Tensor> parameters);

  const std::vector<torch::Tensor>& parameters() const { return parameters_; }
  const torch::Tensor& values() const { return values_; }        // [numel], detached
  const torch::Tensor& gradients() const { return gradients_; }  // [numel]
  int64_t numel() const { return values_.numel(); }

  void zero_grad() { gradients_.zero_(); }
  // Scales the gradients so that their global L2 norm is at most `max_norm`, as
  // torch::nn::utils::clip_grad_norm_ (coefficient max_norm / (norm + 1e-6), capped at 1).
  // Returns the norm before clipping.
  double clip_grad_norm(double max_norm);

 private:
  std::vector<torch::Tensor> parameters_;
  torch::Tensor values_, gradients_;
};

}  // namespace tendril::nn
