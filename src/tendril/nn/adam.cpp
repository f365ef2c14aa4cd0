#include "tendril/nn/adam.hpp"

#include <cmath>

#include "tendril/core/error.hpp"

namespace tendril::nn {

Adam::Adam(int64_t parameter_count, const Options& options)
    : options_(options),
      first_moment_(Eigen::VectorXf::Zero(parameter_count)),
      second_moment_(Eigen::VectorXf::Zero(parameter_count)) {}

void Adam::step(Eigen::Ref<Eigen::VectorXf> parameters,
                const Eigen::Ref<const Eigen::VectorXf>& gradient) {
  ++steps_;
  const auto beta1 = static_cast<float>(options_.beta1);
  const auto beta2 = static_cast<float>(options_.beta2);
  const double correction1 = 1.0 - std::pow(options_.beta1, static_cast<double>(steps_));
  const double correction2 = 1.0 - std::pow(options_.beta2, static_cast<double>(steps_));
  const auto step_size = static_cast<float>(options_.learning_rate / correction1);
  const auto root_correction2 = static_cast<float>(std::sqrt(correction2));
  const auto epsilon = static_cast<float>(options_.epsilon);
  // One fused pass over the three buffers (the update is memory-bound at these sizes).
  float* theta = parameters.data();
  const float* g = gradient.data();
  float* m = first_moment_.data();
  float* v = second_moment_.data();
  const Eigen::Index n = parameters.size();
#pragma omp simd
  for (Eigen::Index i = 0; i < n; ++i) {
    m[i] = beta1 * m[i] + (1.0f - beta1) * g[i];
    v[i] = beta2 * v[i] + (1.0f - beta2) * g[i] * g[i];
    theta[i] -= step_size * m[i] / (std::sqrt(v[i]) / root_correction2 + epsilon);
  }
}

void Adam::set_state(int64_t steps, const Eigen::VectorXf& first_moment,
                     const Eigen::VectorXf& second_moment) {
  require(steps >= 0, "negative step count", "nn::Adam");
  require(
      first_moment.size() == first_moment_.size() && second_moment.size() == second_moment_.size(),
      "optimizer state has " + std::to_string(first_moment.size()) + " parameters, expected " +
          std::to_string(first_moment_.size()),
      "nn::Adam");
  steps_ = steps;
  first_moment_ = first_moment;
  second_moment_ = second_moment;
}

}  // namespace tendril::nn
