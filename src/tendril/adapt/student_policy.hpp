#pragma once

#include <Eigen/Core>

#include "tendril/adapt/multi_output_gp.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// BOAC's student π_i (seed 002 §IV-B): a Gaussian-process local inverse model of the robot
// that maps (the current state x, the desired state x^d) to a command τ — one GP per command
// dimension over the concatenated input [x, x^d] (the MSE surrogate loss of the paper is the
// GP's squared-error likelihood). Its data are transitions reformed as in eq. (3): the command
// τ_t that took x_t to x_{t+1} is the target for the input [x_t, x_{t+1}], so asked for
// x^d = x_{t+1} it answers τ_t.
//
// The GP's prior mean is a linear map of the input (a choice; the paper names no mean
// function): a ridge regression of τ on [x, x^d], refitted with the hyper-parameters, and the GP
// models what it leaves. A constant mean would answer targets beyond the data with the mean
// command; the arm's pressure-to-tip map is smooth enough that the linear part carries the
// student toward targets a few centimetres past the states it has seen.
class StudentPolicy {
 public:
  StudentPolicy(int state_dim, int command_dim, GpOptions options,
                HyperparameterSharing sharing = HyperparameterSharing::shared);

  // D ← D ∪ {([x_t, x_{t+1}], τ_t)}: conditions the GP on the transition (O(n²)).
  void add(const Eigen::VectorXd& state, const Eigen::VectorXd& next_state,
           const Eigen::VectorXd& command);
  // Refits the linear mean and the GP's hyper-parameters (marginal likelihood) on the
  // transitions held — the first time from the data's scales, later from the last fit. Returns
  // its wall time, s.
  double fit_hyperparameters(Rng& rng);
  // π_i(x, x^d): the linear mean plus the GP's posterior mean, clipped to [lower, upper].
  Eigen::VectorXd act(const Eigen::VectorXd& state, const Eigen::VectorXd& desired) const;
  void set_command_bounds(double lower, double upper);

  int size() const { return gp_.size(); }
  const MultiOutputGp& gp() const { return gp_; }

 private:
  Eigen::VectorXd linear_mean(const Eigen::VectorXd& input) const;
  void refit_linear_mean();

  int state_dim_;
  MultiOutputGp gp_;
  // τ ≈ weights_ᵀ ((input − input_mean_) / input_scale_) + bias_ (zero until the first fit).
  Eigen::MatrixXd weights_;
  Eigen::VectorXd bias_, input_mean_, input_scale_;
  double lower_ = -1.0, upper_ = 1.0;
  bool fitted_ = false;
};

}  // namespace tendril::adapt
