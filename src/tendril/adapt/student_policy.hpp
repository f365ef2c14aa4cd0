#pragma once

#include <Eigen/Core>

#include "tendril/adapt/multi_output_gp.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// BOAC's student π_i (seed 002 §IV-B): a Gaussian-process local inverse model of the robot
// that maps (the current state x, the desired state x^d) to a command τ — one GP per command
// dimension over the concatenated input [x, x^d], fitted to the mean of its targets (the MSE
// surrogate loss of the paper is the GP's squared-error likelihood). Its data are transitions
// reformed as in eq. (3): the command τ_t that took x_t to x_{t+1} is the target for the input
// [x_t, x_{t+1}], so asked for x^d = x_{t+1} it answers τ_t.
class StudentPolicy {
 public:
  StudentPolicy(int state_dim, int command_dim, GpOptions options,
                HyperparameterSharing sharing = HyperparameterSharing::shared);

  // D ← D ∪ {([x_t, x_{t+1}], τ_t)}: conditions the GP on the transition (O(n²)).
  void add(const Eigen::VectorXd& state, const Eigen::VectorXd& next_state,
           const Eigen::VectorXd& command);
  // Refits the hyper-parameters (marginal likelihood) on the transitions held, the first time
  // from the data's scales, later from the last fit. Returns its wall time, s.
  double fit_hyperparameters(Rng& rng);
  // π_i(x, x^d): the posterior mean of τ, clipped to [lower, upper].
  Eigen::VectorXd act(const Eigen::VectorXd& state, const Eigen::VectorXd& desired) const;
  void set_command_bounds(double lower, double upper);

  int size() const { return gp_.size(); }
  const MultiOutputGp& gp() const { return gp_; }

 private:
  int state_dim_;
  MultiOutputGp gp_;
  double lower_ = -1.0, upper_ = 1.0;
  bool fitted_ = false;
};

}  // namespace tendril::adapt
