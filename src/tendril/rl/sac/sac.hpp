#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/q_critics.hpp"
#include "tendril/rl/sac/sac_config.hpp"
#include "tendril/rl/sac/squashed_gaussian.hpp"

namespace tendril::rl {

// Soft Actor-Critic (Haarnoja et al. 2018, "Soft Actor-Critic Algorithms and Applications",
// Algorithm 1), as Stable-Baselines3 implements it: twin Q critics with Polyak targets, a
// tanh-squashed diagonal Gaussian policy whose mean and log-std (clamped to [−20, 2]) are two
// linear heads on one trunk, and the entropy coefficient α tuned towards a target entropy.
// Box action spaces only.
class Sac : public OffPolicyAlgorithm {
 public:
  Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed);

  const SacConfig& config() const { return config_; }
  double entropy_coefficient() const;

 protected:
  void act(const Eigen::Ref<const Eigen::MatrixXf>& observations, ActMode mode, Rng& rng,
           Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void save_state(CheckpointWriter& writer) const override;
  std::function<void()> prepare_load(CheckpointReader& reader) override;

 private:
  // One reparameterised draw a = tanh(μ + σ ε) per column, with the actor pass behind it.
  struct PolicySample {
    nn::DenseMlp::Tape tape;
    SquashedGaussianSample distribution;
  };
  void sample_policy(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
                     PolicySample& sample) const;

  SacConfig config_;
  double target_entropy_ = 0.0;
  nn::DenseMlp actor_;  // observation → hidden → [μ; log σ]
  Eigen::VectorXf actor_parameters_, actor_gradient_;
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
};

}  // namespace tendril::rl
