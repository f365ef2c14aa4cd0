#include "tendril/nn/gradient.hpp"

#include <cmath>

namespace tendril::nn {

double clip_grad_norm(Eigen::Ref<Eigen::VectorXf> gradient, double max_norm) {
  const double norm = gradient.norm();
  const double coefficient = max_norm / (norm + 1e-6);
  if (coefficient < 1.0) gradient *= static_cast<float>(coefficient);
  return norm;
}

void polyak_update(Eigen::Ref<Eigen::VectorXf> target,
                   const Eigen::Ref<const Eigen::VectorXf>& online, double tau) {
  const auto t = static_cast<float>(tau);
  target = (1.0f - t) * target + t * online;
}

}  // namespace tendril::nn
