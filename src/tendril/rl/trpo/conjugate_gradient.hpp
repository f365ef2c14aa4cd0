#pragma once

#include <torch/torch.h>

#include <functional>

namespace tendril::rl {

// Solves A x = b for symmetric positive-definite A given only products v ↦ A v, by at most
// `max_steps` conjugate-gradient iterations (Nocedal & Wright, "Numerical Optimization",
// Algorithm 5.2), stopping early once the squared residual falls below `residual_tolerance`.
// TRPO uses it with the Fisher-vector product to find the natural-gradient direction F⁻¹g
// without forming F (Schulman et al. 2015, appendix C).
torch::Tensor conjugate_gradient(const std::function<torch::Tensor(const torch::Tensor&)>& product,
                                 const torch::Tensor& b, int64_t max_steps,
                                 double residual_tolerance = 1e-10);

}  // namespace tendril::rl
