#include "tendril/adapt/student_policy.hpp"

#include <algorithm>
#include <chrono>

#include "tendril/adapt/hyperparameter_search.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

constexpr const char* kWhere = "adapt::StudentPolicy";

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
    : state_dim_(state_dim), gp_(2 * state_dim, command_dim, std::move(options), sharing) {}

void StudentPolicy::add(const Eigen::VectorXd& state, const Eigen::VectorXd& next_state,
                        const Eigen::VectorXd& command) {
  gp_.add(joined(state, next_state, state_dim_), command);
}

double StudentPolicy::fit_hyperparameters(Rng& rng) {
  const auto start = std::chrono::steady_clock::now();
  if (gp_.size() == 0) return 0.0;
  if (!fitted_) {
    // The first search starts at the data's own scales: each length scale the spread of its
    // input (states in mm spread over tens of mm, where the default ℓ = 1 would start the
    // search among needle-thin optima), σ_f² the targets' variance, σ_n² a hundredth of it.
    const auto inputs = gp_.output(0).inputs();
    const Eigen::RowVectorXd mean = inputs.colwise().mean();
    Eigen::VectorXd spread =
        ((inputs.rowwise() - mean).colwise().squaredNorm() / std::max(1, gp_.size() - 1))
            .cwiseSqrt()
            .transpose();
    const GpOptions& options = gp_.output(0).options();
    spread = spread.cwiseMax(options.min_length_scale).cwiseMin(options.max_length_scale);
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
  Eigen::MatrixXd mean, variance;
  gp_.predict(joined(state, desired, state_dim_).transpose(), mean, variance);
  return mean.row(0).transpose().cwiseMax(lower_).cwiseMin(upper_);
}

void StudentPolicy::set_command_bounds(double lower, double upper) {
  require(lower < upper, "the lower command bound must be below the upper", kWhere);
  lower_ = lower;
  upper_ = upper;
}

}  // namespace tendril::adapt
