#include "tendril/rl/trpo/conjugate_gradient.hpp"

namespace tendril::rl {

namespace {
double dot(const Eigen::VectorXf& a, const Eigen::VectorXf& b) {
  return a.cast<double>().dot(b.cast<double>());
}
}  // namespace

Eigen::VectorXf conjugate_gradient(
    const std::function<Eigen::VectorXf(const Eigen::VectorXf&)>& product, const Eigen::VectorXf& b,
    int64_t max_steps, double residual_tolerance, int64_t* products) {
  Eigen::VectorXf x = Eigen::VectorXf::Zero(b.size());
  Eigen::VectorXf residual = b;  // r₀ = b − A x₀ with x₀ = 0
  Eigen::VectorXf direction = b;
  double residual_norm = dot(residual, residual);
  if (products != nullptr) *products = 0;
  for (int64_t step = 0; step < max_steps && residual_norm >= residual_tolerance; ++step) {
    const Eigen::VectorXf a_direction = product(direction);
    if (products != nullptr) ++*products;
    const double alpha = residual_norm / dot(direction, a_direction);
    x += static_cast<float>(alpha) * direction;
    residual -= static_cast<float>(alpha) * a_direction;
    const double next_norm = dot(residual, residual);
    direction = residual + static_cast<float>(next_norm / residual_norm) * direction;
    residual_norm = next_norm;
  }
  return x;
}

}  // namespace tendril::rl
