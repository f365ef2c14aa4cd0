#include "tendril/rl/trpo/conjugate_gradient.hpp"

namespace tendril::rl {

torch::Tensor conjugate_gradient(const std::function<torch::Tensor(const torch::Tensor&)>& product,
                                 const torch::Tensor& b, int64_t max_steps,
                                 double residual_tolerance) {
  torch::Tensor x = torch::zeros_like(b);
  torch::Tensor residual = b.clone();  // r₀ = b − A x₀ with x₀ = 0
  torch::Tensor direction = b.clone();
  double residual_norm = residual.dot(residual).item<double>();
  for (int64_t step = 0; step < max_steps && residual_norm >= residual_tolerance; ++step) {
    const torch::Tensor a_direction = product(direction);
    const double alpha = residual_norm / direction.dot(a_direction).item<double>();
    x += alpha * direction;
    residual -= alpha * a_direction;
    const double next_norm = residual.dot(residual).item<double>();
    direction = residual + (next_norm / residual_norm) * direction;
    residual_norm = next_norm;
  }
  return x;
}

}  // namespace tendril::rl
