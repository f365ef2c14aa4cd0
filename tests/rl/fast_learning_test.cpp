// Learning checks short enough for the default suite (seconds each): every learner must get
// well clear of a random policy on a reference task within a small budget, so that a broken
// update shows up without the `long` tests, whose full thresholds stay in classic_control_test.
//   CartPole-v1: a random policy lasts about 22 steps.   Pendulum-v1: random ≈ −1200.
// Each learner trains three seeds and the median return must clear the threshold; the budgets
// leave room, so that the worst median measured over seeds 0–11 under three OpenBLAS kernel
// paths clears it by 142 (DQN) to 260 (DDPG) — docs/testing.md.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "support/evaluation.hpp"
#include "support/learning_seed.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/trainer.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

constexpr int kSeeds = 3;

// The experiment configs/<name> (or YAML text) with `overrides` (key=value, as `--set`) and the
// k-th of the test's seeds: the config's seed + k, moved by TENDRIL_TEST_SEED_OFFSET.
Experiment experiment_for(const std::string& name, const std::vector<std::string>& overrides,
                          int k) {
  Config config = name.ends_with(".yaml")
                      ? Config::load_file(std::string(TENDRIL_CONFIG_DIR) + "/" + name)
                      : Config::parse(name, "inline experiment");
  for (const std::string& item : overrides) {
    const auto equals = item.find('=');
    config.set(item.substr(0, equals), item.substr(equals + 1));
  }
  const uint64_t seed = testing::learning_seed(config.get_or<uint64_t>("seed", 0) + k);
  config.set("seed", std::to_string(seed));
  return Experiment::from_config(config);
}

// Trains one experiment and returns the mean return of its final deterministic policy over 10
// fresh episodes (raw rewards).
double final_policy_return(const Experiment& experiment) {
  auto env = make_vec_env(experiment.env);
  auto algorithm = make_algorithm(experiment, *env);
  const auto start = std::chrono::steady_clock::now();
  algorithm->learn(experiment.n_timesteps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto evaluation_env = make_evaluation_env(experiment.env, *env);
  const envs::RunResult result =
      testing::evaluate(algorithm->policy(), *evaluation_env, 10, experiment.seed + 1000);
  std::printf("%s seed %llu, %lld steps in %.1f s: return %.1f ± %.1f\n",
              experiment.algorithm.c_str(), static_cast<unsigned long long>(experiment.seed),
              static_cast<long long>(algorithm->num_timesteps()), seconds, result.mean_return(),
              result.std_return());
  return result.mean_return();
}

// Trains one experiment with periodic evaluations that keep the best model (as SB3's
// EvalCallback does) and returns that model's mean return over 10 fresh episodes.
double best_policy_return(const Experiment& experiment) {
  const std::filesystem::path run =
      std::filesystem::temp_directory_path() /
      ("tendril_fast_learning_" + experiment.algorithm + "_" + std::to_string(::getpid()) + "_" +
       std::to_string(experiment.seed));
  std::filesystem::remove_all(run);
  const TrainResult trained = train(experiment, run, {.stop_at = std::nullopt, .quiet = true});
  const std::unique_ptr<Policy> policy = load_policy(run / "best_model.policy");
  const auto evaluation_env = envs::make(experiment.env.id, experiment.env.params);
  const envs::RunResult result =
      testing::evaluate(*policy, *evaluation_env, 10, experiment.seed + 1000);
  std::printf("%s seed %llu, %lld steps in %.1f s: best model (%lld steps) return %.1f ± %.1f\n",
              experiment.algorithm.c_str(), static_cast<unsigned long long>(experiment.seed),
              static_cast<long long>(trained.timesteps), trained.seconds,
              static_cast<long long>(trained.best_eval_timesteps), result.mean_return(),
              result.std_return());
  std::filesystem::remove_all(run);
  return result.mean_return();
}

// The median over kSeeds seeds of `score(experiment)`.
template <typename Score>
double median_over_seeds(const std::string& name, const std::vector<std::string>& overrides,
                         const Score& score) {
  std::vector<double> returns;
  for (int k = 0; k < kSeeds; ++k) returns.push_back(score(experiment_for(name, overrides, k)));
  std::sort(returns.begin(), returns.end());
  return returns[kSeeds / 2];
}

double median_final_return(const std::string& name, const std::vector<std::string>& overrides) {
  return median_over_seeds(name, overrides, final_policy_return);
}

// Each learner trains with three seeds and the median of their returns must clear the threshold.
// Measured margins (the worst median over seed offsets 0–11 under three OpenBLAS kernel paths):
// docs/testing.md.
TEST(FastLearning, PpoBalancesCartPole) {
  EXPECT_GE(median_final_return("ppo/cartpole.yaml", {"n_timesteps=60000"}), 300.0);
}

TEST(FastLearning, TrpoBalancesCartPole) {
  EXPECT_GE(median_final_return("algorithm: trpo\nenv: {id: CartPole-v1, n_envs: 4}\n"
                                "algo: {n_steps: 256, gamma: 0.98, gae_lambda: 0.9}\n"
                                "n_timesteps: 30000\nseed: 0\n",
                                {}),
            300.0);
}

TEST(FastLearning, SacSwingsUpPendulum) {
  EXPECT_GE(median_final_return("sac/pendulum.yaml", {"n_timesteps=10000", "algo.net_arch=[64, 64]",
                                                      "algo.batch_size=64"}),
            -400.0);
}

TEST(FastLearning, Td3SwingsUpPendulum) {
  EXPECT_GE(
      median_final_return("td3/pendulum.yaml", {"n_timesteps=15000", "algo.learning_starts=1000",
                                                "algo.net_arch=[64, 64]", "algo.batch_size=64"}),
      -450.0);
}

TEST(FastLearning, DdpgSwingsUpPendulum) {
  EXPECT_GE(
      median_final_return("ddpg/pendulum.yaml", {"n_timesteps=15000", "algo.learning_starts=1000",
                                                 "algo.net_arch=[64, 64]", "algo.batch_size=64"}),
      -450.0);
}

// DQN can lose a solved CartPole within a run (configs/dqn/cartpole.yaml), so, as the long test
// does, the run keeps the model of its best periodic evaluation.
TEST(FastLearning, DqnBalancesCartPole) {
  EXPECT_GE(median_over_seeds(
                "dqn/cartpole.yaml",
                {"n_timesteps=30000", "algo.net_arch=[64, 64]", "algo.learning_rate=1e-3",
                 "eval.freq=2500", "eval.episodes=10", "eval.save_best=true", "checkpoint_freq=0"},
                best_policy_return),
            200.0);
}

}  // namespace
}  // namespace tendril::rl
