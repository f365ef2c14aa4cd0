#include <gtest/gtest.h>

#include <cstdio>

#include "support/evaluation.hpp"
#include "support/learning_seed.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

// Stable-Baselines3's identity checks (tests/test_identity.py): the policy must learn to repeat
// its observation, scoring ≥ 90 of 100 per episode over 20 deterministic evaluation episodes,
// within a budget of a few thousand steps. γ is small because actions do not affect the future.
envs::RunResult train_and_evaluate(const std::string& id, const std::string& env_params,
                                   const std::string& algo, int64_t budget, uint64_t seed) {
  VecEnvOptions options;
  options.id = id;
  options.params = Config::parse(env_params);
  options.n_envs = 1;
  auto env = make_vec_env(options);
  seed = testing::learning_seed(seed);
  Ppo ppo(*env, PpoConfig::from_config(Config::parse(algo)), seed);
  ppo.learn(budget);
  EXPECT_GE(ppo.num_timesteps(), budget);
  auto evaluation_env = envs::make(id, Config::parse(env_params));
  envs::RunResult result = testing::evaluate(ppo.policy(), *evaluation_env, 20, seed + 1000);
  std::printf("%s: return %.1f\n", id.c_str(), result.mean_return());
  return result;
}

TEST(PpoIdentity, SolvesDiscreteIdentity) {
  const envs::RunResult result = train_and_evaluate(
      "Identity-v0", "n: 10", "n_steps: 512\ngamma: 0.5\npolicy: {net_arch: [64]}\n", 5000, 1);
  EXPECT_EQ(result.episodes.size(), 20u);
  EXPECT_GE(result.mean_return(), 90.0);
}

TEST(PpoIdentity, SolvesBoxIdentity) {
  // SB3's test_continuous: IdentityEnvBox(eps=0.5), 3000 steps for PPO.
  const envs::RunResult result =
      train_and_evaluate("IdentityBox-v0", "eps: 0.5",
                         "n_steps: 512\ngamma: 0.5\npolicy: {net_arch: [64]}\n", 3000, 1);
  EXPECT_GE(result.mean_return(), 90.0);
}

TEST(PpoIdentity, SolvesNarrowBoxIdentityWithMoreSteps) {
  // A tenth of SB3's tolerance: the policy mean must track the state within ±0.05.
  const envs::RunResult result = train_and_evaluate(
      "IdentityBox-v0", "eps: 0.05",
      "n_steps: 512\ngamma: 0.5\nlearning_rate: 1e-3\npolicy: {net_arch: [64]}\n", 60000, 1);
  EXPECT_GE(result.mean_return(), 90.0);
}

}  // namespace
}  // namespace tendril::rl
