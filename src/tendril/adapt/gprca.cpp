#include "tendril/adapt/gprca.hpp"

#include <chrono>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {

// The vector a loop function returned, checked for size and finiteness.
Eigen::VectorXd checked(Eigen::VectorXd value, Eigen::Index size, const char* what) {
  if (value.size() != size) {
    throw Error(std::string(what) + " returned " + std::to_string(value.size()) +
                    " values, expected " + std::to_string(size),
                "GprcaCompensator");
  }
  if (!value.allFinite()) {
    throw Error(std::string(what) + " returned non-finite values", "GprcaCompensator");
  }
  return value;
}

}  // namespace

GpOptions default_compensator_options() {
  GpOptions options;
  options.kernel = KernelType::squared_exponential;
  options.window = 500;
  options.restarts = 0;
  return options;
}

GprcaCompensator::GprcaCompensator(int action_dim, int observation_dim, CompensationOptions options)
    : options_(std::move(options)),
      action_dim_(action_dim),
      observation_dim_(observation_dim),
      gp_(action_dim, observation_dim, options_.gp, options_.sharing),
      rng_(options_.seed),
      pending_actions_(options_.retrain_every > 0 ? options_.retrain_every : 1, action_dim),
      pending_errors_(options_.retrain_every > 0 ? options_.retrain_every : 1, observation_dim) {
  require(options_.steps_per_episode >= 1, "steps_per_episode must be at least 1",
          "GprcaCompensator");
  require(options_.retrain_every >= 1, "retrain_every must be at least 1", "GprcaCompensator");
  require(options_.search_every >= 0, "search_every must be non-negative", "GprcaCompensator");
  require(options_.search_below >= 0, "search_below must be non-negative", "GprcaCompensator");
}

Eigen::VectorXd GprcaCompensator::compensation(const Eigen::VectorXd& action) const {
  if (gp_.size() == 0) return Eigen::VectorXd::Zero(observation_dim_);
  Eigen::MatrixXd mean, variance;
  gp_.predict(action.transpose(), mean, variance);
  return mean.row(0).transpose();
}

void GprcaCompensator::retrain() {
  for (int i = 0; i < pending_; ++i) {
    gp_.add(pending_actions_.row(i).transpose(), pending_errors_.row(i).transpose());
  }
  pending_ = 0;
  const bool scheduled = options_.search_every > 0 && retrains_ % options_.search_every == 0;
  if (scheduled || gp_.size() <= options_.search_below) gp_.optimize_hyperparameters(rng_);
  ++retrains_;
}

double GprcaCompensator::search_hyperparameters() {
  const auto start = std::chrono::steady_clock::now();
  if (gp_.size() > 0) gp_.optimize_hyperparameters(rng_);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<CompensationStep> GprcaCompensator::run_episode(const CompensationLoop& loop) {
  require(loop.policy && loop.model && loop.reset && loop.step,
          "policy, model, reset and step must all be set", "GprcaCompensator");
  std::vector<CompensationStep> steps;
  steps.reserve(options_.steps_per_episode);
  Eigen::VectorXd observation = checked(loop.reset(), observation_dim_, "reset");
  Eigen::VectorXd previous = observation;  // x_{−1} = x_0
  Eigen::VectorXd compensation = Eigen::VectorXd::Zero(observation_dim_);
  for (int t = 0; t < options_.steps_per_episode; ++t) {
    CompensationStep step;
    step.observation = observation;
    step.compensation = compensation;
    step.action = checked(loop.policy(observation + compensation), action_dim_, "policy");
    step.prediction =
        checked(loop.model(observation, previous, step.action), observation_dim_, "model");
    step.next_observation = checked(loop.step(step.action), observation_dim_, "step");
    // eq. (5): D ← D ∪ (τ_t, e_{t+1}), e_{t+1} = x̂_{t+1} − x_{t+1}.
    pending_actions_.row(pending_) = step.action.transpose();
    pending_errors_.row(pending_) = (step.prediction - step.next_observation).transpose();
    const auto start = std::chrono::steady_clock::now();
    if (++pending_ == options_.retrain_every) {
      retrain();
      step.retrained = true;
    }
    // Alg. 2 line 5: c_{t+1} = G(π_θ(s_t)).
    compensation = this->compensation(step.action);
    step.update_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    previous = observation;
    observation = step.next_observation;
    steps.push_back(std::move(step));
    if (loop.finished && loop.finished(observation)) break;
  }
  return steps;
}

}  // namespace tendril::adapt
