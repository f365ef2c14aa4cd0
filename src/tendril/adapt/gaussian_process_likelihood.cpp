// The log marginal likelihood of a GaussianProcess, its gradient, and the hyper-parameter search.
#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>
#include <utility>

#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/adapt/hyperparameter_search.hpp"
#include "tendril/adapt/likelihood.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {
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
  LikelihoodWorkspace workspace;
  return log_marginal_likelihood(log_parameters, gradient, workspace);
}

double GaussianProcess::log_marginal_likelihood(const Eigen::VectorXd& log_parameters,
                                                Eigen::VectorXd* gradient,
                                                LikelihoodWorkspace& workspace) const {
  if (log_parameters.size() != input_dim_ + 2) {
    throw Error(std::to_string(log_parameters.size()) + " log-parameters, expected " +
                    std::to_string(input_dim_ + 2),
                "GaussianProcess::log_marginal_likelihood");
  }
  if (!log_parameters.allFinite()) {
    throw Error("log-parameters are not finite", "GaussianProcess::log_marginal_likelihood");
  }
  const Eigen::VectorXd residual = targets().array() - prior_mean_;
  return adapt::log_marginal_likelihood(options_.kernel, inputs(), residual, log_parameters,
                                        gradient, workspace);
}

double GaussianProcess::optimize_hyperparameters(Rng& rng) {
  require(size_ > 0, "no data to fit hyper-parameters to",
          "GaussianProcess::optimize_hyperparameters");
  Eigen::VectorXd lower, upper;
  log_parameter_bounds(options_, input_dim_, target_scale(targets()), lower, upper);
  LikelihoodWorkspace workspace;
  const SmoothObjective objective = [&](const Eigen::VectorXd& theta, Eigen::VectorXd& gradient) {
    return log_marginal_likelihood(theta, &gradient, workspace);
  };
  set_hyperparameters(from_log_parameters(search_log_parameters(
      objective, lower, upper, to_log_parameters(hyperparameters_), options_, rng)));
  return log_marginal_likelihood();
}

}  // namespace tendril::adapt
