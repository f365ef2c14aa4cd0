#include "tendril/adapt/hyperparameter_search.hpp"

#include <cmath>
#include <limits>

namespace tendril::adapt {

void log_parameter_bounds(const GpOptions& options, int input_dim, double target_variance,
                          Eigen::VectorXd& lower, Eigen::VectorXd& upper) {
  const int d = input_dim;
  lower.resize(d + 2);
  upper.resize(d + 2);
  lower.head(d).setConstant(std::log(options.min_length_scale));
  upper.head(d).setConstant(std::log(options.max_length_scale));
  lower[d] = std::log(options.min_signal_variance * target_variance);
  upper[d] = std::log(options.max_signal_variance * target_variance);
  lower[d + 1] = std::log(options.min_noise_variance * target_variance);
  upper[d + 1] = std::log(options.max_noise_variance * target_variance);
}

Eigen::VectorXd search_log_parameters(const SmoothObjective& log_likelihood,
                                      const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                      const Eigen::VectorXd& first_start, const GpOptions& options,
                                      Rng& rng) {
  BoxMaximum best;
  best.value = -std::numeric_limits<double>::infinity();
  best.point = first_start.cwiseMax(lower).cwiseMin(upper);
  Eigen::VectorXd start = first_start;
  for (int attempt = 0; attempt <= options.restarts; ++attempt) {
    if (attempt > 0) {
      for (Eigen::Index k = 0; k < start.size(); ++k) start[k] = rng.uniform(lower[k], upper[k]);
    }
    BoxMaximum found = maximize_in_box(log_likelihood, lower, upper, start, options.max_evaluations,
                                       options.relative_tolerance);
    if (found.value > best.value) best = std::move(found);
  }
  return best.point;
}

double target_scale(const Eigen::Ref<const Eigen::VectorXd>& values) {
  if (values.size() == 0) return 1.0;
  const double spread = (values.array() - values.mean()).square().mean();
  return spread > 0.0 ? spread : 1.0;
}

}  // namespace tendril::adapt
