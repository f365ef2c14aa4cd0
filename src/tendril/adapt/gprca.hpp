#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "tendril/adapt/multi_output_gp.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// What GPRCA runs against, as plain functions (observations and actions in the policy's units):
// the trained policy, the dynamics model it was trained in, and the robot.
struct CompensationLoop {
  // π_θ: the action for an observation (the compensated one, s_t).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& observation)> policy;
  // F_φ: the model's next observation x̂_{t+1} given the robot's real history X = [x_t, x_{t−1}]
  // and the action (seed 002, Sec. IV-C: fed from the robot, so the error carries no drift).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& observation,
                                const Eigen::VectorXd& previous_observation,
                                const Eigen::VectorXd& action)>
      model;
  // The robot: its observation at the start of an episode, and after each action.
  std::function<Eigen::VectorXd()> reset;
  std::function<Eigen::VectorXd(const Eigen::VectorXd& action)> step;
  // Optional: whether an episode ends at a (raw) observation — goal reached, collision.
  std::function<bool(const Eigen::VectorXd& observation)> finished;
};

// Squared exponential, a window of the latest 500 points, no random restarts (each search starts
// from the previous retrain's hyper-parameters).
GpOptions default_compensator_options();

struct CompensationOptions {
  int steps_per_episode = 100;  // L_E (seed 002: 100 in S0–S1, 150 in S2–S4)
  int retrain_every = 5;        // n_B: steps between retrains
  // Hyper-parameter search at every `search_every`-th retrain (warm-started from the last; 0:
  // never inside an episode), and at every retrain while the GP holds at most `search_below`
  // points (cheap there). Between searches a retrain conditions the GP on the new points only,
  // O(n²) each. search_hyperparameters() searches between episodes.
  int search_every = 1;
  int search_below = 0;
  // The compensator: one GP per observation dimension, the action as input. A window keeps
  // the latest points.
  GpOptions gp = default_compensator_options();
  HyperparameterSharing sharing = HyperparameterSharing::per_output;
  uint64_t seed = 0;
};

// One step of the loop, all in the policy's observation units.
struct CompensationStep {
  Eigen::VectorXd observation;       // x_t, the robot's
  Eigen::VectorXd compensation;      // c_t
  Eigen::VectorXd action;            // τ_t = π_θ(s_t), s_t = x_t + c_t
  Eigen::VectorXd prediction;        // x̂_{t+1} = F_φ([x_t, x_{t−1}], τ_t)
  Eigen::VectorXd next_observation;  // x_{t+1}, the robot's
  bool retrained = false;            // whether the compensator was retrained after this step
  // Wall time of the compensator's work after the step: the retrain (when due) and the
  // prediction of c_{t+1} — what must fit in the control period.
  double update_seconds = 0.0;
};

// GPRCA, the Gaussian-process recurrent cerebellar architecture of seed 002 (Nazeer et al.,
// Sec. IV-C, eq. (5), Alg. 2), after Porrill et al.'s recurrent architecture: a GP G maps the
// policy's action to the motor error e_{t+1} = x̂_{t+1} − x_{t+1}; its prediction at the action
// just taken, c_{t+1} = G(τ_t), is added to the next observation the policy sees,
// s_{t+1} = x_{t+1} + c_{t+1}. When c ≈ e the policy sees what the model would have shown it.
// The data D = {(τ_t, e_{t+1})} grow across episodes; G is retrained every n_B steps.
class GprcaCompensator {
 public:
  GprcaCompensator(int action_dim, int observation_dim, CompensationOptions options = {});

  // Runs one episode of Alg. 2 (lines 4–10) against `loop`: at most steps_per_episode steps,
  // fewer when `finished` says so. A callable returning a vector of the wrong size or with
  // non-finite values raises Error naming it.
  std::vector<CompensationStep> run_episode(const CompensationLoop& loop);

  // G's prediction for an action (zero before the first retrain).
  Eigen::VectorXd compensation(const Eigen::VectorXd& action) const;
  // Maximises the likelihood over the hyper-parameters on the points held (between episodes,
  // while the robot is reset); no-op without points. Returns the wall time, s.
  double search_hyperparameters();
  const MultiOutputGp& gp() const { return gp_; }
  int retrains() const { return retrains_; }

 private:
  void retrain();

  CompensationOptions options_;
  int action_dim_, observation_dim_;
  MultiOutputGp gp_;
  Rng rng_;
  Eigen::MatrixXd pending_actions_, pending_errors_;  // D_i, rows
  int pending_ = 0;
  int retrains_ = 0;
};

}  // namespace tendril::adapt
