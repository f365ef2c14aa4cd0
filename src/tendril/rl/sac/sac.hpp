#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/q_critics.hpp"
#include "tendril/rl/sac/actor_penalty.hpp"
#include "tendril/rl/sac/sac_config.hpp"
#include "tendril/rl/sac/squashed_gaussian_policy.hpp"

namespace tendril::rl {

// Soft Actor-Critic (Haarnoja et al. 2018, "Soft Actor-Critic Algorithms and Applications",
// Algorithm 1), as Stable-Baselines3 implements it: twin Q critics with Polyak targets, a
// tanh-squashed diagonal Gaussian policy whose mean and log-std (clamped to [−20, 2]) are two
// linear heads on one trunk, and the entropy coefficient α tuned towards a target entropy.
// Optionally gSDE exploration instead of independent Gaussian noise (`use_sde`). Box action
// spaces only.
class Sac : public OffPolicyAlgorithm {
 public:
  Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed);

  const SacConfig& config() const { return config_; }
  const Policy& policy() const override { return policy_; }
  double entropy_coefficient() const;
  // The twin Q critics (over [observation; action in [−1, 1]]).
  const QCritics& critics() const { return critics_; }
  // Adds `penalty` to the actor's objective from the next update on (nullptr removes it);
  // borrowed. Not part of checkpoints: whoever sets it restores it.
  void set_actor_penalty(ActorPenalty* penalty) { actor_penalty_ = penalty; }

 protected:
  void explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
               Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void collection_started() override { resample_exploration_ = true; }
  void write_own_state(ArchiveWriter& writer) const override;
  std::function<void()> read_own_state(const ArchiveReader& reader) override;

 private:
  using PolicySample = SquashedGaussianPolicy::Sample;

  // One step of log α (when learned) and one of the actor on the policy's sample `current_` of
  // `batch_`; each returns its loss.
  double update_entropy_coefficient(double learning_rate);
  double update_actor(float ent_coef, double learning_rate);

  SacConfig config_;
  double target_entropy_ = 0.0;
  SquashedGaussianPolicy policy_;   // the actor: its parameters are trained in place
  Eigen::VectorXf actor_gradient_;  // of the network's weights, then gSDE's log σ
  nn::Adam actor_optimizer_;
  QCritics critics_;
  Eigen::VectorXf log_ent_coef_;  // one entry: log α
  ActorPenalty* actor_penalty_ = nullptr;
  nn::Adam ent_coef_optimizer_;

  // Scratch of the update, kept to avoid allocations.
  ReplayBuffer::Batch batch_;
  PolicySample current_, next_;
  Eigen::MatrixXf critic_inputs_, value_gradient_, input_gradient_, actor_output_gradient_;
  std::vector<Eigen::MatrixXf> actor_scratch_;
  Eigen::MatrixXf exploration_;                   // E of the current gradient step (gSDE)
  std::vector<Eigen::MatrixXf> env_exploration_;  // E of each env while collecting (gSDE)
  bool resample_exploration_ = true;
  int64_t steps_since_resample_ = 0;
};

}  // namespace tendril::rl
