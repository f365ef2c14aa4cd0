#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/nn/feature_heads.hpp"
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
//
// With a policy head (seed 001, thesis §5.1.2, Fig. 5.2) actor and critics read the encoded
// observation [LayerNorm(head(history)); direct] (rl::ObservationEncoder), one head shared by
// them. A frozen head never changes, so the replay buffer keeps encoded observations, computed
// once when collected. A trainable head runs in every update: the critics and the actor read it
// with its online weights, the critic targets with a Polyak-averaged target copy (updated with
// the critics'), and one Adam step (learning rate and gradient-norm clip of the networks) follows
// the gradient of the critic loss plus that of the actor losses of the step with respect to the
// head's weights, taken before any of the step's updates.
class Sac : public OffPolicyAlgorithm {
 public:
  Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed);

  const SacConfig& config() const { return config_; }
  const Policy& policy() const override { return policy_; }
  double entropy_coefficient() const;
  // The twin Q critics (over [observation; action in [−1, 1]]).
  const QCritics& critics() const { return critics_; }
  // The head's weights and their target copy (empty without a head; equal for a frozen head).
  const Eigen::VectorXf& head_parameters() const { return policy_.head_parameters(); }
  const Eigen::VectorXf& head_target_parameters() const { return head_target_; }
  // Adds `penalty` to the actor's objective from the next update on (nullptr removes it);
  // borrowed. Not part of checkpoints: whoever sets it restores it. It sees the observations the
  // replay buffer keeps (a frozen head's features when the policy has one).
  void set_actor_penalty(ActorPenalty* penalty) { actor_penalty_ = penalty; }

 protected:
  void explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
               Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void collection_started() override { resample_exploration_ = true; }
  void store_observations(const Eigen::Ref<const Eigen::MatrixXf>& observations,
                          Eigen::MatrixXf& stored) override;
  void write_own_state(ArchiveWriter& writer) const override;
  std::function<void()> read_own_state(const ArchiveReader& reader) override;

 private:
  using PolicySample = SquashedGaussianPolicy::Sample;

  Sac(envs::VecEnv& env, const SacConfig& config, uint64_t seed, nn::CreatedHead head);
  // A head whose weights the updates change.
  bool head_trains() const { return config_.head && config_.head->trainable; }
  // A frozen head's encodings of the observations of a collection step, computed for all the
  // envs at once whenever one of them changed (so an encoding never depends on which envs
  // changed).
  const Eigen::MatrixXf& encode_collected(const Eigen::Ref<const Eigen::MatrixXf>& observations);
  // The actor's input for observations of the envs: the observations, or their encodings.
  Eigen::Ref<const Eigen::MatrixXf> actor_inputs(
      const Eigen::Ref<const Eigen::MatrixXf>& observations);
  // Encodes the batch for a trainable head (online and target weights); otherwise the
  // buffer's rows are the networks' inputs already.
  void encode_batch();
  // One step of a trainable head from the gradient gathered in encoded_gradient_.
  void update_head(double learning_rate);

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
  Eigen::VectorXf head_target_, head_gradient_;
  nn::Adam head_optimizer_;

  // Scratch of the update, kept to avoid allocations.
  ReplayBuffer::Batch batch_;
  PolicySample current_, next_;
  Eigen::MatrixXf critic_inputs_, value_gradient_, input_gradient_, actor_output_gradient_;
  // The networks' inputs of the batch: its observations (through the online head), its next
  // observations through the online and through the target head.
  const Eigen::MatrixXf* inputs_ = nullptr;
  const Eigen::MatrixXf* next_inputs_ = nullptr;
  const Eigen::MatrixXf* target_next_inputs_ = nullptr;
  ObservationEncoder::Pass batch_pass_, next_pass_, target_pass_, collect_pass_;
  Eigen::MatrixXf encoded_gradient_, actor_input_gradient_;  // ∂L/∂ encoded observations
  Eigen::MatrixXf collected_, collected_encoded_;            // encode_collected's last call
  std::vector<Eigen::MatrixXf> actor_scratch_;
  Eigen::MatrixXf exploration_;                   // E of the current gradient step (gSDE)
  std::vector<Eigen::MatrixXf> env_exploration_;  // E of each env while collecting (gSDE)
  bool resample_exploration_ = true;
  int64_t steps_since_resample_ = 0;
};

}  // namespace tendril::rl
