#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tendril/core/archive.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/rl/observer.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/q_critics.hpp"
#include "tendril/rl/replay_buffer.hpp"

namespace tendril::safety {

// The cost critic's settings; the thesis gives none for its Lagrangian baselines (Table 6.1),
// so each is a labelled choice in configs/safety/.
struct CostCriticSettings {
  double gamma = 0.9;  // γ_risk
  std::vector<int64_t> net_arch = {64, 64};
  double learning_rate = 3e-4;
  double tau = 0.005;  // Polyak rate of the target critics
  int64_t buffer_size = 100000;
  int64_t batch_size = 128;
  int64_t learning_starts = 1000;  // stored transitions before the first update
  int64_t gradient_steps = 1;      // per vector-env step

  // Reads the keys above from a mapping (every key optional), checking ranges.
  static CostCriticSettings from_config(const Config& config);
};

// The safety critic Q_risk of Recovery RL (Thananjeyan et al. 2021, §IV-A; the constrained
// baselines of seed 001 Table 6.1 use it as their cost critic): the discounted probability that
// the task policy π leads into X_unsafe,
//
//   Q_risk(s, a) = c' + (1 − c') γ_risk E_{a'∼π(·|s')} Q_risk(s', a'),
//
// with c' = 1 when the step ends in X_unsafe (the environment's "cost" info) — a violation ends
// the critic's episode, so Q_risk ∈ [0, 1]. Twin critics whose larger value is used (risk is
// over- rather than under-estimated) and Polyak-averaged targets. It learns as an observer of
// the task agent's rollouts, from a replay buffer of its own, with π's actions at s' drawn from
// the task policy. Actions inside are in [−1, 1], as the off-policy agents store them.
class CostCritic : public rl::Observer {
 public:
  CostCritic(const rl::Policy& task_policy, const CostCriticSettings& settings, uint64_t seed);

  void on_step(const rl::StepEvent& event) override;

  // Q_risk (the larger twin) of each column of [observations; actions in [−1, 1]].
  const Eigen::VectorXf& values(const Eigen::MatrixXf& observations,
                                const Eigen::MatrixXf& actions);
  // After `values`: adds ∂(Σ_j weight · Q_risk_j)/∂actions to `action_gradient`.
  void add_action_gradient(float weight, Eigen::Ref<Eigen::MatrixXf> action_gradient);

  const CostCriticSettings& settings() const { return settings_; }
  const rl::ReplayBuffer& buffer() const { return buffer_; }
  int64_t updates() const { return updates_; }
  double last_loss() const { return last_loss_; }

  // Its state — critics, targets, optimizer, buffer, draws, counts — in and out of a checkpoint
  // under `prefix`; `prepare_load` reads and checks it and returns the action that installs it.
  void save(ArchiveWriter& writer, const std::string& prefix) const;
  std::function<void()> prepare_load(const ArchiveReader& reader, const std::string& prefix);

 private:
  void train();

  const rl::Policy& task_policy_;
  CostCriticSettings settings_;
  rl::QCritics critics_;
  rl::ReplayBuffer buffer_;
  Rng rng_;
  int64_t updates_ = 0;
  double last_loss_ = 0.0;
  rl::ReplayBuffer::Batch batch_;
  envs::BatchMatrix next_observation_rows_, next_action_rows_;
  Eigen::MatrixXf inputs_, next_actions_, value_gradient_, input_gradient_;
  Eigen::VectorXf values_;
  std::vector<Eigen::Index> larger_;
};

}  // namespace tendril::safety
