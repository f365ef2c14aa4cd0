#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>

namespace tendril::rl {

// Solves A x = b for symmetric positive-definite A given only products v ↦ A v, by at most
// `max_steps` conjugate-gradient iterations (Nocedal & Wright, "Numerical Optimization",
// Algorithm 5.2), stopping early once the squared residual falls below `residual_tolerance`.
// TRPO uses it with the Fisher-vector product to find the natural-gradient direction F⁻¹g
// without forming F (Schulman et al. 2015, appendix C). `products` counts the calls of
// `product` when given.
Eigen::VectorXf conjugate_gradient(
    const std::function<Eigen::VectorXf(const Eigen::VectorXf&)>& product, const Eigen::VectorXf& b,
    int64_t max_steps, double residual_tolerance = 1e-10, int64_t* products = nullptr);

}  // namespace tendril::rl
