#include "tendril/adapt/student_policy.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>

#include "tendril/adapt/hyperparameter_search.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

constexpr const char* kWhere = "adapt::StudentPolicy";
// Ridge penalty of the linear mean, relative to the standardised inputs' mean square (1).
constexpr double kRidge = 1e-3;

Eigen::VectorXd joined(const Eigen::VectorXd& state, const Eigen::VectorXd& desired, int size) {
  require(state.size() == size && desired.size() == size,
          "states must have " + std::to_string(size) + " values", kWhere);
  Eigen::VectorXd input(2 * size);
  input << state, desired;
  return input;
}

}  // namespace

StudentPolicy::StudentPolicy(int state_dim, int command_dim, GpOptions options,
                             HyperparameterSharing sharing)
    : state_dim_(state_dim),
      gp_(2 * state_dim, command_dim, std::move(options), sharing),
      weights_(Eigen::MatrixXd::Zero(2 * state_dim, command_dim)),
      bias_(Eigen::VectorXd::Zero(command_dim)),
      input_mean_(Eigen::VectorXd::Zero(2 * state_dim)),
      input_scale_(Eigen::VectorXd::Ones(2 * state_dim)) {}

Eigen::VectorXd StudentPolicy::linear_mean(const Eigen::VectorXd& input) const {
  return weights_.transpose() * ((input - input_mean_).cwiseQuotient(input_scale_)) + bias_;
}

void StudentPolicy::add(const Eigen::VectorXd& state, const Eigen::VectorXd& next_state,
                        const Eigen::VectorXd& command) {
  const Eigen::VectorXd input = joined(state, next_state, state_dim_);
  require(command.size() == gp_.output_dim() && command.allFinite(),
          "the command must have " + std::to_string(gp_.output_dim()) + " finite values", kWhere);
  gp_.add(input, command - linear_mean(input));
}

void StudentPolicy::refit_linear_mean() {
  const int n = gp_.size(), outputs = gp_.output_dim();
  const Eigen::MatrixXd inputs = gp_.output(0).inputs();
  Eigen::MatrixXd targets(n, outputs);  // the commands themselves: residual + old linear mean
  for (int k = 0; k < outputs; ++k) targets.col(k) = gp_.output(k).targets();
  for (int i = 0; i < n; ++i) {
    targets.row(i) += linear_mean(inputs.row(i).transpose()).transpose();
  }
  input_mean_ = inputs.colwise().mean().transpose();
  input_scale_ =
      ((inputs.rowwise() - input_mean_.transpose()).colwise().squaredNorm() / std::max(1, n - 1))
          .cwiseSqrt()
          .transpose()
          .cwiseMax(1e-9);
  const Eigen::MatrixXd standard = (inputs.rowwise() - input_mean_.transpose()).array().rowwise() /
                                   input_scale_.transpose().array();
  const Eigen::RowVectorXd target_mean = targets.colwise().mean();
  Eigen::MatrixXd gram = standard.transpose() * standard;
  gram.diagonal().array() += kRidge * n;
  weights_ = gram.ldlt().solve(standard.transpose() * (targets.rowwise() - target_mean));
  bias_ = target_mean.transpose();
  Eigen::MatrixXd residuals(n, outputs);
  for (int i = 0; i < n; ++i) {
    residuals.row(i) = targets.row(i) - linear_mean(inputs.row(i).transpose()).transpose();
  }
  gp_.fit(inputs, residuals);
}

double StudentPolicy::fit_hyperparameters(Rng& rng) {
  const auto start = std::chrono::steady_clock::now();
  if (gp_.size() == 0) return 0.0;
  refit_linear_mean();
  if (!fitted_) {
    // The first search starts at the data's own scales: each length scale the spread of its
    // input (states in mm spread over tens of mm, where the default ℓ = 1 would start the
    // search among needle-thin optima), σ_f² the residuals' variance, σ_n² a hundredth of it.
    const GpOptions& options = gp_.output(0).options();
    const Eigen::VectorXd spread =
        input_scale_.cwiseMax(options.min_length_scale).cwiseMin(options.max_length_scale);
    for (int k = 0; k < gp_.output_dim(); ++k) {
      GpHyperparameters start_point;
      start_point.length_scales = spread;
      start_point.signal_variance = target_scale(gp_.output(k).targets());
      start_point.noise_variance = 1e-2 * start_point.signal_variance;
      gp_.output(k).set_hyperparameters(start_point);
    }
    fitted_ = true;
  }
  gp_.optimize_hyperparameters(rng);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Eigen::VectorXd StudentPolicy::act(const Eigen::VectorXd& state,
                                   const Eigen::VectorXd& desired) const {
  require(gp_.size() > 0, "the student has no data yet", kWhere);
  const Eigen::VectorXd input = joined(state, desired, state_dim_);
  Eigen::MatrixXd mean, variance;
  gp_.predict(input.transpose(), mean, variance);
  return (linear_mean(input) + mean.row(0).transpose()).cwiseMax(lower_).cwiseMin(upper_);
}

void StudentPolicy::set_command_bounds(double lower, double upper) {
  require(lower < upper, "the lower command bound must be below the upper", kWhere);
  lower_ = lower;
  upper_ = upper;
}

}  // namespace tendril::adapt
