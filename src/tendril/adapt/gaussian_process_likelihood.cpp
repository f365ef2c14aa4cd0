// The log marginal likelihood of a GaussianProcess, its gradient, and the hyper-parameter search.
#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "tendril/adapt/box_maximizer.hpp"
#include "tendril/adapt/cholesky.hpp"
#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

// What the search reports for hyper-parameters whose kernel matrix does not factor even with
// jitter: far below any attainable likelihood, finite so that L-BFGS's line search backs off.
constexpr double kUnfactorable = -1e100;

double half_log_two_pi() { return 0.5 * std::log(2.0 * std::numbers::pi); }

}  // namespace

Eigen::VectorXd GaussianProcess::to_log_parameters(const GpHyperparameters& hyperparameters) {
  const auto d = hyperparameters.length_scales.size();
  Eigen::VectorXd theta(d + 2);
  theta.head(d) = hyperparameters.length_scales.array().log();
  theta[d] = std::log(hyperparameters.signal_variance);
  theta[d + 1] = std::log(hyperparameters.noise_variance);
  return theta;
}

GpHyperparameters GaussianProcess::from_log_parameters(const Eigen::VectorXd& log_parameters) {
  const auto d = log_parameters.size() - 2;
  require(d > 0, "log-parameters need at least one length scale", "GaussianProcess");
  return {log_parameters.head(d).array().exp(), std::exp(log_parameters[d]),
          std::exp(log_parameters[d + 1])};
}

double GaussianProcess::log_marginal_likelihood() const {
  if (size_ == 0) return 0.0;
  const Eigen::VectorXd residual = targets().array() - prior_mean_;
  return -0.5 * residual.dot(weights_) - cholesky_factor().diagonal().array().log().sum() -
         size_ * half_log_two_pi();
}

double GaussianProcess::log_marginal_likelihood(const Eigen::VectorXd& log_parameters,
                                                Eigen::VectorXd* gradient) const {
  if (log_parameters.size() != input_dim_ + 2) {
    throw Error(std::to_string(log_parameters.size()) + " log-parameters, expected " +
                    std::to_string(input_dim_ + 2),
                "GaussianProcess::log_marginal_likelihood");
  }
  if (!log_parameters.allFinite()) {
    throw Error("log-parameters are not finite", "GaussianProcess::log_marginal_likelihood");
  }
  if (gradient) gradient->setZero(input_dim_ + 2);
  const int n = size_;
  if (n == 0) return 0.0;
  const GpHyperparameters hyper = from_log_parameters(log_parameters);
  const ArdKernel kernel(options_.kernel, hyper.length_scales, hyper.signal_variance);
  const auto x = inputs();

  Eigen::MatrixXd squared_distances;
  kernel.squared_distances(x, x, squared_distances);
  Eigen::MatrixXd kernel_matrix = squared_distances;  // K_f, without noise
  kernel.apply_shape(kernel_matrix);
  Eigen::MatrixXd factor(n, n);
  double jitter = 0.0;
  if (!factor_with_jitter(kernel_matrix, hyper.noise_variance, hyper.signal_variance, factor,
                          jitter)) {
    return kUnfactorable;
  }
  const auto lower = std::as_const(factor).triangularView<Eigen::Lower>();
  const Eigen::VectorXd residual = targets().array() - prior_mean_;
  Eigen::VectorXd alpha = residual;
  lower.solveInPlace(alpha);
  lower.transpose().solveInPlace(alpha);
  const double value =
      -0.5 * residual.dot(alpha) - factor.diagonal().array().log().sum() - n * half_log_two_pi();
  if (!gradient) return value;

  // W = ααᵀ − K⁻¹, with K⁻¹ = L⁻ᵀL⁻¹.
  Eigen::MatrixXd w = Eigen::MatrixXd::Identity(n, n);
  lower.solveInPlace(w);
  lower.transpose().solveInPlace(w);
  w = alpha * alpha.transpose() - w;

  auto& g = *gradient;
  const int d = input_dim_;
  g[d] = 0.5 * (w.array() * kernel_matrix.array()).sum();      // ∂K/∂log σ_f² = K_f
  g[d + 1] = 0.5 * hyper.noise_variance * w.diagonal().sum();  // ∂K/∂log σ_n² = σ_n² I
  // ∂K_ik/∂log ℓ_j = σ_f² g(r_ik) Δ_ikj² / ℓ_j² (ArdKernel::slope).
  kernel.apply_slope(squared_distances);
  w.array() *= squared_distances.array();
  for (int j = 0; j < d; ++j) {
    const auto column = x.col(j).array();
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += (w.col(k).array() * (column - column[k]).square()).sum();
    g[j] = 0.5 * sum / (hyper.length_scales[j] * hyper.length_scales[j]);
  }
  return value;
}

double GaussianProcess::optimize_hyperparameters(Rng& rng) {
  require(size_ > 0, "no data to fit hyper-parameters to",
          "GaussianProcess::optimize_hyperparameters");
  const int d = input_dim_;
  const auto y = targets().array();
  const double spread = (y - y.mean()).square().mean();
  const double target_variance = spread > 0.0 ? spread : 1.0;

  Eigen::VectorXd lower(d + 2), upper(d + 2);
  lower.head(d).setConstant(std::log(options_.min_length_scale));
  upper.head(d).setConstant(std::log(options_.max_length_scale));
  lower[d] = std::log(options_.min_signal_variance * target_variance);
  upper[d] = std::log(options_.max_signal_variance * target_variance);
  lower[d + 1] = std::log(options_.min_noise_variance * target_variance);
  upper[d + 1] = std::log(options_.max_noise_variance * target_variance);

  const SmoothObjective objective = [this](const Eigen::VectorXd& theta,
                                           Eigen::VectorXd& gradient) {
    return log_marginal_likelihood(theta, &gradient);
  };
  BoxMaximum best;
  best.value = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd start = to_log_parameters(hyperparameters_);
  for (int attempt = 0; attempt <= options_.restarts; ++attempt) {
    if (attempt > 0) {
      for (int k = 0; k < d + 2; ++k) start[k] = rng.uniform(lower[k], upper[k]);
    }
    BoxMaximum found = maximize_in_box(objective, lower, upper, start, options_.max_evaluations,
                                       options_.relative_tolerance);
    if (found.value > best.value) best = std::move(found);
  }
  set_hyperparameters(from_log_parameters(best.point));
  return log_marginal_likelihood();
}

}  // namespace tendril::adapt
