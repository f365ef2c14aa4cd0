#include "tendril/safety/co_trainer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "one_step.hpp"
#include "support/learning_seed.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/dqn/dqn.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"
#include "tendril/safety/safety_critic.hpp"

namespace tendril::safety {
namespace {

std::unique_ptr<envs::VecEnv> double_integrator(const std::string& params) {
  rl::VecEnvOptions options;
  options.id = "Safety/DoubleIntegrator-v0";
  options.params = Config::parse(params);
  return rl::make_vec_env(options);
}

rl::DqnConfig small_dqn() {
  return rl::DqnConfig::from_config(
      Config::parse("net_arch: [32, 32]\nlearning_starts: 0\nbatch_size: 32\ngamma: 0.9\n"
                    "target_update_interval: 100\nbuffer_size: 1000"));
}

// One hand-made vector step of one environment: x → x' with action `action`.
void feed(SafetyCoTrainer& trainer, const Eigen::Vector3f& x, float action,
          const Eigen::Vector3f& next, bool done, int64_t timesteps) {
  trainer.on_step(
      testing::OneStep(x, Eigen::VectorXf::Constant(1, action), next, done).event(timesteps));
}

TEST(SafetyCoTrainer, GateClosesAtTheFirstUnsafeTransitionAndReopensWithTheEpisode) {
  auto env = double_integrator("discrete_actions: 3\nhorizon: 100");
  rl::Dqn agent(*env, small_dqn(), 1);
  auto single = envs::make("Safety/DoubleIntegrator-v0", Config::parse("horizon: 100"));
  const auto constraint = constraint_of(*single);
  CoTrainingSettings settings;
  settings.learning_starts = 1000;  // no updates in this test
  settings.unsafe_samples_per_step = 0;
  const SafetyReward reward(0.9);
  SafetyCoTrainer trainer(agent, *constraint, reward, settings, 1000, 7);

  feed(trainer, {1.0f, 1.0f, 0.0f}, 2.0f, {1.5f, 1.0f, 0.01f}, false, 1);   // safe → safe
  feed(trainer, {1.5f, 1.0f, 0.01f}, 2.0f, {2.1f, 1.0f, 0.02f}, false, 2);  // enters X_unsafe
  feed(trainer, {2.1f, 1.0f, 0.02f}, 2.0f, {2.5f, 1.0f, 0.03f}, false, 3);  // gated
  feed(trainer, {2.5f, 1.0f, 0.03f}, 0.0f, {2.9f, 1.0f, 0.04f}, true, 4);   // gated; episode ends
  feed(trainer, {0.0f, 0.0f, 0.0f}, 1.0f, {0.0f, 0.0f, 0.01f}, false, 5);   // new episode
  feed(trainer, {0.0f, 0.0f, 0.99f}, 1.0f, {0.0f, 0.0f, 1.0f}, true, 6);    // its time limit

  const rl::ReplayBuffer& buffer = trainer.buffer();
  ASSERT_EQ(buffer.size(), 4);
  EXPECT_EQ(trainer.gated_transitions(), 2);
  EXPECT_EQ(trainer.unsafe_entries(), 1);
  // l(x) = min(2 − 1, 3 − 1)/2 = 0.5 for the first transition.
  EXPECT_FLOAT_EQ(buffer.reward(0), 0.5f);
  EXPECT_FALSE(buffer.terminated(0));
  EXPECT_FLOAT_EQ(buffer.action(0)[0], 2.0f);  // a discrete index is stored as is
  // Entering at t = 1 (0.01 · 100): −1/(0.9 · 0.1), and the transition terminates.
  EXPECT_NEAR(buffer.reward(1), -1.0 / (0.9 * 0.1), 1e-4);
  EXPECT_TRUE(buffer.terminated(1));
  EXPECT_FLOAT_EQ(buffer.next_observation(1)[0], 2.1f);
  EXPECT_FLOAT_EQ(buffer.reward(2), 1.0f);  // l at the origin
  EXPECT_FALSE(buffer.terminated(2));
  // The time limit T ends the safety agent's finite-horizon episode (§6.2.1): no bootstrap.
  EXPECT_FLOAT_EQ(buffer.reward(3), 1.0f);
  EXPECT_TRUE(buffer.terminated(3));
}

TEST(SafetyCoTrainer, UnsafeSamplesCarryTheSupervisedTarget) {
  auto env = double_integrator("discrete_actions: 3");
  rl::Dqn agent(*env, small_dqn(), 1);
  auto single = envs::make("Safety/DoubleIntegrator-v0");
  const auto constraint = constraint_of(*single);
  CoTrainingSettings settings;
  settings.learning_starts = 1000;
  settings.unsafe_samples_per_step = 3;
  SafetyCoTrainer trainer(agent, *constraint, SafetyReward(0.9), settings, 1000, 7);
  feed(trainer, {1.0f, 1.0f, 0.0f}, 2.0f, {1.5f, 1.0f, 0.005f}, false, 1);
  ASSERT_EQ(trainer.buffer().size(), 4);
  for (int64_t i = 1; i < 4; ++i) {
    EXPECT_TRUE(constraint->unsafe(trainer.buffer().observation(i)));
    EXPECT_FLOAT_EQ(trainer.buffer().reward(i), -10.0f);
    EXPECT_TRUE(trainer.buffer().terminated(i));
  }
}

// Co-training a DQN task agent and a DQN safety agent on the discrete double integrator: the
// safety value is positive deep inside the analytic safe set and negative in a state that must
// leave it, and the same seed gives the same safety network.
std::pair<Eigen::VectorXf, std::pair<double, double>> co_train(uint64_t seed, int64_t steps) {
  auto env = double_integrator("discrete_actions: 5\nhorizon: 100");
  rl::DqnConfig task_config = small_dqn();
  task_config.exploration_fraction = 0.5;
  rl::Dqn task(*env, task_config, seed);
  rl::Dqn safety_agent(*env, small_dqn(), seed + 1);
  auto single = envs::make("Safety/DoubleIntegrator-v0", Config::parse("horizon: 100"));
  const auto constraint = constraint_of(*single);
  CoTrainingSettings settings;
  settings.learning_starts = 200;
  SafetyCoTrainer trainer(safety_agent, *constraint, SafetyReward(0.9), settings, steps, seed);
  task.learn(steps, rl::Observers{&trainer});
  const auto& q_policy = dynamic_cast<const rl::QGreedyPolicy&>(safety_agent.policy());
  const DqnSafetyCritic critic(q_policy);
  const double inside = critic.state_value(Eigen::Vector3f(0.0f, 0.0f, 0.0f));
  const double doomed = critic.state_value(Eigen::Vector3f(1.9f, 2.8f, 0.0f));
  return {q_policy.parameters(), {inside, doomed}};
}

TEST(SafetyCoTrainer, LearnsTheSignOfTheSafeSetAndIsReproducible) {
  const uint64_t seed = tendril::testing::learning_seed(3);
  const auto first = co_train(seed, 4000);
  const auto again = co_train(seed, 4000);
  std::printf("dqn safety value inside %.3f, doomed %.3f\n", first.second.first,
              first.second.second);
  EXPECT_TRUE(first.first == again.first);
  EXPECT_GT(first.second.first, 0.0);
  EXPECT_LT(first.second.second, 0.0);
}

// The continuous path: a SAC safety agent beside a SAC task agent; its critic, read through
// SacSafetyCritic (env-unit actions scaled to [−1, 1]), orders a state deep inside the safe set
// above one that must leave it, and the same seed repeats the run exactly.
std::pair<Eigen::VectorXf, std::pair<double, double>> co_train_sac(uint64_t seed, int64_t steps) {
  auto env = double_integrator("horizon: 100");
  const Config algo = Config::parse(
      "net_arch: [32, 32]\nlearning_starts: 200\nbatch_size: 64\ngamma: 0.9\nbuffer_size: 5000");
  rl::Sac task(*env, rl::SacConfig::from_config(algo), seed);
  rl::Sac safety_agent(*env, rl::SacConfig::from_config(algo), seed + 1);
  auto single = envs::make("Safety/DoubleIntegrator-v0", Config::parse("horizon: 100"));
  const auto constraint = constraint_of(*single);
  CoTrainingSettings settings;
  settings.learning_starts = 200;
  SafetyCoTrainer trainer(safety_agent, *constraint, SafetyReward(0.9), settings, steps, seed);
  task.learn(steps, rl::Observers{&trainer});
  EXPECT_FALSE(trainer.last_stats().empty());
  const SacSafetyCritic critic(safety_agent.policy(), safety_agent.critics());
  const double inside = critic.state_value(Eigen::Vector3f(0.0f, 0.0f, 0.0f));
  const double doomed = critic.state_value(Eigen::Vector3f(1.9f, 2.8f, 0.0f));
  return {safety_agent.critics().parameters(), {inside, doomed}};
}

TEST(SafetyCoTrainer, SacSafetyAgentLearnsAndIsReproducible) {
  const uint64_t seed = tendril::testing::learning_seed(5);
  const auto first = co_train_sac(seed, 3000);
  const auto again = co_train_sac(seed, 3000);
  std::printf("sac safety value inside %.3f, doomed %.3f\n", first.second.first,
              first.second.second);
  EXPECT_TRUE(first.first == again.first);
  EXPECT_GT(first.second.first, first.second.second);
  EXPECT_LT(first.second.second, 0.0);
}

}  // namespace
}  // namespace tendril::safety
