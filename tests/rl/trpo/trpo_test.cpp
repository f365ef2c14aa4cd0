#include "tendril/rl/trpo/trpo.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "support/evaluation.hpp"
#include "support/learning_seed.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

TEST(TrpoConfig, DefaultsPresetAndErrors) {
  const TrpoConfig sb3 = TrpoConfig::from_config(Config::parse("{}"));
  EXPECT_EQ(sb3.common.n_steps, 2048);
  EXPECT_DOUBLE_EQ(sb3.target_kl, 0.01);
  EXPECT_EQ(sb3.cg_max_steps, 15);
  EXPECT_DOUBLE_EQ(sb3.cg_damping, 0.1);
  EXPECT_DOUBLE_EQ(sb3.line_search_shrinking_factor, 0.8);
  EXPECT_EQ(sb3.line_search_max_iter, 10);
  EXPECT_EQ(sb3.n_critic_updates, 10);
  EXPECT_EQ(sb3.batch_size, 128);
  EXPECT_DOUBLE_EQ(sb3.learning_rate, 1e-3);
  const TrpoConfig v2 = TrpoConfig::from_config(Config::parse("preset: trpo_v2\n"));
  EXPECT_EQ(v2.common.n_steps, 1024);
  EXPECT_DOUBLE_EQ(v2.common.gae_lambda, 0.98);
  EXPECT_EQ(v2.cg_max_steps, 10);
  EXPECT_DOUBLE_EQ(v2.cg_damping, 0.01);
  EXPECT_EQ(v2.n_critic_updates, 3);
  EXPECT_DOUBLE_EQ(v2.learning_rate, 3e-4);
  EXPECT_THROW(TrpoConfig::from_config(Config::parse("max_kl: 0.01\n")), Error);
  EXPECT_THROW(TrpoConfig::from_config(Config::parse("policy: {shared_trunk: true}\n")), Error);
  EXPECT_THROW(TrpoConfig::from_config(Config::parse("line_search_shrinking_factor: 1.5\n")),
               Error);
}

std::unique_ptr<envs::VecEnv> pendulum(int n_envs) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  options.n_envs = n_envs;
  return make_vec_env(options);
}

envs::RunResult train_and_evaluate(const std::string& id, const std::string& env_params,
                                   const std::string& algo, int64_t budget, uint64_t seed) {
  VecEnvOptions options;
  options.id = id;
  options.params = Config::parse(env_params);
  auto env = make_vec_env(options);
  seed = testing::learning_seed(seed);
  Trpo trpo(*env, TrpoConfig::from_config(Config::parse(algo)), seed);
  trpo.learn(budget);
  auto evaluation_env = envs::make(id, Config::parse(env_params));
  envs::RunResult result = testing::evaluate(trpo.policy(), *evaluation_env, 20, seed + 1000);
  std::printf("%s: return %.1f\n", id.c_str(), result.mean_return());
  return result;
}

// SB3's identity thresholds: ≥ 90 of 100 per episode over 20 deterministic episodes.
TEST(TrpoIdentity, SolvesDiscreteIdentity) {
  const envs::RunResult result = train_and_evaluate(
      "Identity-v0", "n: 10", "n_steps: 512\ngamma: 0.5\npolicy: {net_arch: [64]}\n", 5000, 1);
  EXPECT_GE(result.mean_return(), 90.0);
}

TEST(TrpoIdentity, SolvesBoxIdentity) {
  const envs::RunResult result =
      train_and_evaluate("IdentityBox-v0", "eps: 0.5",
                         "n_steps: 512\ngamma: 0.5\npolicy: {net_arch: [64]}\n", 5000, 1);
  EXPECT_GE(result.mean_return(), 90.0);
}

TEST(Trpo, SameSeedSameParametersAndCheckpointsAreAlgorithmSpecific) {
  const std::string algo = "n_steps: 128\nbatch_size: 64\nn_critic_updates: 2\n";
  std::vector<Eigen::VectorXf> parameters;
  for (const uint64_t seed : {4, 4, 5}) {
    auto env = pendulum(2);
    Trpo trpo(*env, TrpoConfig::from_config(Config::parse(algo)), seed);
    trpo.learn(512);
    parameters.push_back(trpo.actor_critic().parameters());
  }
  EXPECT_EQ(parameters[0], parameters[1]);
  EXPECT_NE(parameters[0], parameters[2]);  // another seed, another run

  const auto file = std::filesystem::temp_directory_path() /
                    ("tendril_trpo_test_" + std::to_string(::getpid()) + ".ckpt");
  auto env = pendulum(1);
  Trpo trpo(*env, TrpoConfig::from_config(Config::parse(algo)), 4);
  trpo.learn(256);
  trpo.save(file);
  Trpo restored(*env, TrpoConfig::from_config(Config::parse(algo)), 5);
  restored.load(file);
  envs::BatchMatrix observations(2, 3);
  observations << 1, 0, 0, 0, 1, -3;
  EXPECT_EQ(trpo.predict(observations, true), restored.predict(observations, true));
  Ppo ppo(*env, PpoConfig::from_config(Config::parse("n_steps: 128\n")), 4);
  EXPECT_THROW(ppo.load(file), Error);  // a TRPO checkpoint is not a PPO one
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace tendril::rl
