#include "tendril/adapt/multi_output_gp.hpp"

#include <cmath>
#include <string>

#include "tendril/adapt/hyperparameter_search.hpp"
#include "tendril/adapt/likelihood.hpp"
#include "tendril/adapt/number_text.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

MultiOutputGp::MultiOutputGp(int input_dim, int output_dim, GpOptions options,
                             HyperparameterSharing sharing)
    : sharing_(sharing) {
  require(output_dim > 0, "output_dim must be positive", "MultiOutputGp");
  outputs_.reserve(output_dim);
  for (int k = 0; k < output_dim; ++k) outputs_.emplace_back(input_dim, options);
}

void MultiOutputGp::fit(const Eigen::Ref<const Eigen::MatrixXd>& inputs,
                        const Eigen::Ref<const Eigen::MatrixXd>& targets) {
  const std::string where = "MultiOutputGp::fit";
  if (targets.cols() != output_dim()) {
    throw Error("targets have " + std::to_string(targets.cols()) + " columns, expected " +
                    std::to_string(output_dim()),
                where);
  }
  if (targets.rows() != inputs.rows()) {
    throw Error(std::to_string(inputs.rows()) + " inputs but " + std::to_string(targets.rows()) +
                    " targets",
                where);
  }
  for (Eigen::Index i = 0; i < targets.rows(); ++i) {
    for (int k = 0; k < output_dim(); ++k) {
      if (!std::isfinite(targets(i, k))) {
        throw Error("target " + std::to_string(i) + " of output " + std::to_string(k) + " is " +
                        number_text(targets(i, k)),
                    where);
      }
    }
  }
  for (int k = 0; k < output_dim(); ++k) outputs_[k].fit(inputs, targets.col(k));
}

void MultiOutputGp::add(const Eigen::Ref<const Eigen::VectorXd>& input,
                        const Eigen::Ref<const Eigen::VectorXd>& target) {
  const std::string where = "MultiOutputGp::add";
  if (target.size() != output_dim()) {
    throw Error("target has " + std::to_string(target.size()) + " values, expected " +
                    std::to_string(output_dim()),
                where);
  }
  if (!target.allFinite()) throw Error("target is not finite", where);
  if (input.size() != input_dim() || !input.allFinite()) {
    throw Error("input must be " + std::to_string(input_dim()) + " finite values", where);
  }
  for (int k = 0; k < output_dim(); ++k) outputs_[k].add(input, target[k]);
}

void MultiOutputGp::remove_oldest() {
  for (auto& output : outputs_) output.remove_oldest();
}

void MultiOutputGp::clear() {
  for (auto& output : outputs_) output.clear();
}

double MultiOutputGp::optimize_hyperparameters(Rng& rng) {
  if (sharing_ == HyperparameterSharing::shared) return optimize_shared_hyperparameters(rng);
  const uint64_t seed = rng.next_u64();
  double total = 0.0;
  for (int k = 0; k < output_dim(); ++k) {
    Rng stream(seed, k);
    total += outputs_[k].optimize_hyperparameters(stream);
  }
  return total;
}

double MultiOutputGp::optimize_shared_hyperparameters(Rng& rng) {
  const int n = size();
  require(n > 0, "no data to fit hyper-parameters to", "MultiOutputGp::optimize_hyperparameters");
  const int d = input_dim();
  const GpOptions& options = outputs_.front().options();
  // Standardised residuals: output k's r_k / s_k, with s_k² its target variance. In these units
  // the variances are the relative ones, and the bounds apply as they stand.
  Eigen::MatrixXd residuals(n, output_dim());
  Eigen::VectorXd scales(output_dim());
  for (int k = 0; k < output_dim(); ++k) {
    const auto& output = outputs_[k];
    scales[k] = target_scale(output.targets());
    residuals.col(k) = (output.targets().array() - output.prior_mean()) / std::sqrt(scales[k]);
  }
  Eigen::VectorXd lower, upper;
  log_parameter_bounds(options, d, 1.0, lower, upper);
  Eigen::VectorXd start = GaussianProcess::to_log_parameters(outputs_.front().hyperparameters());
  start.tail(2).array() -= std::log(scales[0]);
  LikelihoodWorkspace workspace;
  const auto inputs = outputs_.front().inputs();
  const SmoothObjective objective = [&](const Eigen::VectorXd& theta, Eigen::VectorXd& gradient) {
    return log_marginal_likelihood(options.kernel, inputs, residuals, theta, &gradient, workspace);
  };
  const Eigen::VectorXd best = search_log_parameters(objective, lower, upper, start, options, rng);
  double total = 0.0;
  for (int k = 0; k < output_dim(); ++k) {
    Eigen::VectorXd theta = best;
    theta.tail(2).array() += std::log(scales[k]);
    outputs_[k].set_hyperparameters(GaussianProcess::from_log_parameters(theta));
    total += outputs_[k].log_marginal_likelihood();
  }
  return total;
}

void MultiOutputGp::predict(const Eigen::Ref<const Eigen::MatrixXd>& inputs, Eigen::MatrixXd& mean,
                            Eigen::MatrixXd& variance, bool with_noise) const {
  mean.resize(inputs.rows(), output_dim());
  variance.resize(inputs.rows(), output_dim());
  Eigen::VectorXd output_mean, output_variance;
  for (int k = 0; k < output_dim(); ++k) {
    outputs_[k].predict(inputs, output_mean, output_variance, with_noise);
    mean.col(k) = output_mean;
    variance.col(k) = output_variance;
  }
}

}  // namespace tendril::adapt
