#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/q_critics.hpp"
#include "tendril/rl/sac/sac_config.hpp"
#include "tendril/rl/sac/squashed_gaussian.hpp"
#include "tendril/rl/sac/state_dependent_noise.hpp"

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
  double entropy_coefficient() const;

 protected:
  void act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
           Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void collection_started() override { resample_exploration_ = true; }
  void save_state(CheckpointWriter& writer) const override;
  std::function<void()> prepare_load(CheckpointReader& reader) override;

 private:
  // One reparameterised draw per column, with the actor pass behind it: a = tanh(μ + σ ε), or
  // with gSDE a = tanh(μ + z W) for the exploration matrix E behind W.
  struct PolicySample {
    nn::DenseMlp::Tape tape;
    SquashedGaussianSample gaussian;
    StateDependentNoiseSample sde;
  };
  // Draws ε from `rng`; with gSDE uses `exploration` as E.
  void sample_policy(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                     const Eigen::MatrixXf& exploration, PolicySample& sample) const;
  const Eigen::MatrixXf& actions_of(const PolicySample& sample) const {
    return config_.use_sde ? sample.sde.actions : sample.gaussian.actions;
  }
  const Eigen::VectorXf& log_probs_of(const PolicySample& sample) const {
    return config_.use_sde ? sample.sde.log_probs : sample.gaussian.log_probs;
  }
  // gSDE: the latent features z (last hidden layer) of the actor pass, and log σ (the actor
  // parameters after the network's).
  const Eigen::MatrixXf& latent_of(const nn::DenseMlp::Tape& tape) const;
  Eigen::Map<const Eigen::MatrixXf> log_std() const;
  Eigen::MatrixXf standard_normal_matrix(Rng& rng) const;  // E, latent × action_size

  SacConfig config_;
  double target_entropy_ = 0.0;
  nn::DenseMlp actor_;  // observation → hidden → [μ; log σ], or μ with gSDE
  int64_t latent_size_ = 0;
  Eigen::VectorXf actor_parameters_, actor_gradient_;  // the network's, then gSDE's log σ
  nn::Adam actor_optimizer_;
  QCritics critics_;
  Eigen::VectorXf log_ent_coef_;  // one entry: log α
  nn::Adam ent_coef_optimizer_;

  // Scratch of the update, kept to avoid allocations.
  ReplayBuffer::Batch batch_;
  PolicySample current_, next_;
  Eigen::MatrixXf critic_inputs_, value_gradient_, input_gradient_, actor_output_gradient_;
  std::vector<Eigen::MatrixXf> actor_scratch_;
  nn::DenseMlp::Tape act_tape_;
  Eigen::MatrixXf exploration_;                   // E of the current gradient step (gSDE)
  std::vector<Eigen::MatrixXf> env_exploration_;  // E of each env while collecting (gSDE)
  bool resample_exploration_ = true;
  int64_t steps_since_resample_ = 0;
};

}  // namespace tendril::rl
