#pragma once

#include <Eigen/Core>

#include "tendril/nn/adam.hpp"
#include "tendril/nn/dense_mlp.hpp"
#include "tendril/rl/action_noise.hpp"
#include "tendril/rl/adam_checkpoint.hpp"
#include "tendril/rl/off_policy_algorithm.hpp"
#include "tendril/rl/q_critics.hpp"
#include "tendril/rl/td3/deterministic_policy.hpp"
#include "tendril/rl/td3/td3_config.hpp"

namespace tendril::rl {

// Twin Delayed DDPG (Fujimoto et al. 2018, "Addressing Function Approximation Error in
// Actor-Critic Methods", Algorithm 1): clipped double-Q targets, target-policy smoothing and
// delayed policy and target updates, over a deterministic tanh actor. With one critic, no
// smoothing and no delay it is DDPG (Lillicrap et al. 2016), which is how SB3 defines DDPG.
// Box action spaces only.
class Td3 : public OffPolicyAlgorithm {
 public:
  Td3(envs::VecEnv& env, const Td3Config& config, uint64_t seed,
      Td3Variant variant = Td3Variant::kTd3);

  const Td3Config& config() const { return config_; }
  const Policy& policy() const override { return policy_; }

 protected:
  void explore(const Eigen::Ref<const Eigen::MatrixXf>& observations, Rng& rng,
               Eigen::MatrixXf& actions) override;
  TrainStats train(int64_t gradient_steps, double progress_remaining) override;
  void episode_ended(int env_index) override { noise_.reset(env_index); }
  void write_own_state(ArchiveWriter& writer) const override;
  std::function<void()> read_own_state(const ArchiveReader& reader) override;

 private:
  Td3Config config_;
  DeterministicPolicy policy_;  // the actor: its parameters are trained in place
  Eigen::VectorXf actor_target_, actor_gradient_;
  nn::Adam actor_optimizer_;
  QCritics critics_;
  ActionNoise noise_;

  ReplayBuffer::Batch batch_;
  nn::DenseMlp::Tape actor_tape_;
  Eigen::MatrixXf next_actions_, critic_inputs_, value_gradient_, input_gradient_;
  std::vector<Eigen::MatrixXf> actor_scratch_;
};

}  // namespace tendril::rl
