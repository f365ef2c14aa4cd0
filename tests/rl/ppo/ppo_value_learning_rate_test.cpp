// PPO with a learning rate for the value network of its own (seed 002 §IV-A3: critic 0.01 →
// 0.001, actor 0.003 → 0.0001), and the softsign mean of seed 002's actor.
#include <gtest/gtest.h>

#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/actor_critic_policy.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

std::unique_ptr<envs::VecEnv> pendulum() {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  options.n_envs = 2;
  return make_vec_env(options);
}

// Separate trunks and no gradient clipping: the policy's update does not depend on the value
// network's parameters within one iteration, nor the value's on the policy's.
const std::string kPpo =
    "n_steps: 128\nbatch_size: 64\nn_epochs: 3\nmax_grad_norm: none\n"
    "learning_rate: 1.0e-3\nlearning_rate_schedule: linear\nlearning_rate_final: 1.0e-4\n";

Eigen::VectorXf train(const std::string& yaml, int64_t steps, int64_t* policy_count = nullptr) {
  auto env = pendulum();
  Ppo ppo(*env, PpoConfig::from_config(Config::parse(yaml)), 5);
  ppo.learn(steps);
  if (policy_count) *policy_count = ppo.actor_critic().network().policy_parameter_count();
  return ppo.actor_critic().parameters();
}

TEST(PpoValueLearningRate, EqualToTheActorsItIsOneAdam) {
  // Adam acts element by element, so two optimizers over the two blocks with the same schedule
  // make the same steps as one over both: bit for bit, over several iterations.
  const Eigen::VectorXf one = train(kPpo, 1024);
  const Eigen::VectorXf two =
      train(kPpo +
                "vf_learning_rate: 1.0e-3\nvf_learning_rate_schedule: linear\n"
                "vf_learning_rate_final: 1.0e-4\n",
            1024);
  EXPECT_TRUE(one == two);
}

TEST(PpoValueLearningRate, OnlyTheValueBlockFollowsIt) {
  // One iteration (2 envs × 128 steps). With vf_learning_rate 10× the actor's, the policy block
  // is what one Adam at the actor's rate gives, and the value block what one Adam at ten times
  // that rate gives.
  int64_t policy_count = 0;
  const Eigen::VectorXf split =
      train(kPpo +
                "vf_learning_rate: 1.0e-2\nvf_learning_rate_schedule: linear\n"
                "vf_learning_rate_final: 1.0e-3\n",
            256, &policy_count);
  const Eigen::VectorXf actor_rate = train(kPpo, 256);
  const Eigen::VectorXf value_rate = train(
      "n_steps: 128\nbatch_size: 64\nn_epochs: 3\nmax_grad_norm: none\n"
      "learning_rate: 1.0e-2\nlearning_rate_schedule: linear\nlearning_rate_final: 1.0e-3\n",
      256);
  const int64_t value_count = split.size() - policy_count;
  ASSERT_GT(policy_count, 0);
  ASSERT_GT(value_count, 0);
  EXPECT_TRUE(split.head(policy_count) == actor_rate.head(policy_count));
  EXPECT_TRUE(split.tail(value_count) == value_rate.tail(value_count));
  EXPECT_FALSE(split.tail(value_count) == actor_rate.tail(value_count));
}

class PpoValueLearningRateFiles : public testing::ScratchDirectoryTest {
 protected:
  PpoValueLearningRateFiles() : ScratchDirectoryTest("ppo_value_lr_test") {}
};

TEST_F(PpoValueLearningRateFiles, BothOptimizersResumeFromACheckpoint) {
  const std::string yaml = kPpo + "vf_learning_rate: 1.0e-2\n";
  auto env = pendulum();
  Ppo first(*env, PpoConfig::from_config(Config::parse(yaml)), 5);
  first.learn(512);
  first.save(directory_ / "half.ckpt");
  first.learn(1024);

  auto other_env = pendulum();
  Ppo resumed(*other_env, PpoConfig::from_config(Config::parse(yaml)), 5);
  resumed.load(directory_ / "half.ckpt");
  resumed.learn(1024);
  EXPECT_TRUE(first.actor_critic().parameters() == resumed.actor_critic().parameters());

  // A checkpoint of one Adam does not load into a learner with two.
  auto single_env = pendulum(), split_env = pendulum();  // an algorithm borrows its env
  Ppo single(*single_env, PpoConfig::from_config(Config::parse(kPpo)), 5);
  single.save(directory_ / "single.ckpt");
  Ppo split(*split_env, PpoConfig::from_config(Config::parse(yaml)), 5);
  EXPECT_THROW(split.load(directory_ / "single.ckpt"), Error);
}

TEST_F(PpoValueLearningRateFiles, ASoftsignMeanStaysWithinOneAndSurvivesThePolicyFile) {
  // pi_output_activation: softsign bounds the Gaussian mean to (−1, 1) whatever the input, and
  // the policy file keeps it.
  const Space observations_space = Space::box(3, -10.0f, 10.0f);
  const Space actions_space = Space::box(2, -5.0f, 5.0f);
  nn::ActorCriticSpec spec;
  spec.activation = nn::Activation::kSoftsign;
  spec.policy_output_activation = nn::Activation::kSoftsign;
  ActorCriticPolicy policy(observations_space, actions_space, spec);
  Rng rng(4);
  policy.parameters().setConstant(1.0f);  // every unit driven far from zero
  envs::BatchMatrix observations(4, 3);
  observations << 1, 0, 8, -1, 0, -8, 0, 1, 3, 0, -1, -3;
  envs::BatchMatrix actions;
  policy.act(observations, /*deterministic=*/true, rng, actions);
  EXPECT_TRUE((actions.array().abs() < 1.0f).all());
  EXPECT_TRUE((actions.array().abs() > 0.9f).any());

  policy.save(directory_ / "softsign.policy");
  const std::unique_ptr<Policy> loaded = load_policy(directory_ / "softsign.policy");
  envs::BatchMatrix loaded_actions;
  loaded->act(observations, true, rng, loaded_actions);
  EXPECT_TRUE(loaded_actions == actions);

  // Without the output activation the same parameters reach the action bounds.
  spec.policy_output_activation.reset();
  ActorCriticPolicy linear(observations_space, actions_space, spec);
  linear.parameters() = policy.parameters();
  linear.act(observations, true, rng, actions);
  EXPECT_TRUE((actions.array().abs() > 4.99f).any());
}

}  // namespace
}  // namespace tendril::rl
