#pragma once

#include <Eigen/Core>

#include "tendril/adapt/box_maximizer.hpp"
#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// The box of θ = (log ℓ_1, …, log ℓ_d, log σ_f², log σ_n²) that `options` allows, with the
// variance bounds taken relative to `target_variance`.
void log_parameter_bounds(const GpOptions& options, int input_dim, double target_variance,
                          Eigen::VectorXd& lower, Eigen::VectorXd& upper);

// The best of L-BFGS climbs of `log_likelihood` in the box: from `first_start` and from
// options.restarts further starts drawn uniformly in the box (log-uniform in the parameters).
Eigen::VectorXd search_log_parameters(const SmoothObjective& log_likelihood,
                                      const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                      const Eigen::VectorXd& first_start, const GpOptions& options,
                                      Rng& rng);

// The variance of `values` about their mean, or 1 when they are all equal (the scale the
// relative variance bounds refer to).
double target_scale(const Eigen::Ref<const Eigen::VectorXd>& values);

}  // namespace tendril::adapt
