// PPO learns TendonArm/Reach-v0 on the robot's twin within a short budget: the experiment
// configs/tendon_arm/ppo_reach.yaml cut to 30,000 steps (about 20 s). Holding the tendons slack
// leaves the tip at rest (50 steps of −|goal − tip| / L: −5.6 over the test's episodes); the
// trained policy's mean return over the same 10 fresh episodes must exceed −2.5. Measured
// (docs/testing.md's procedure): seeds 0–3 natively, 0–1 under OPENBLAS_CORETYPE=Haswell and
// =Zen: −1.07 to −1.25, so a margin of 1.25.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "support/evaluation.hpp"
#include "support/learning_seed.hpp"
#include "tendril/rl/experiment.hpp"
#include "tendril/rl/policy.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

TEST(TendonArmReachLearning, PpoGetsWellClearOfSlackTendonsIn30kSteps) {
  Config config = Config::load_file(std::string(TENDRIL_CONFIG_DIR) + "/tendon_arm/ppo_reach.yaml");
  config.set("n_timesteps", "30000");
  config.set("seed", std::to_string(testing::learning_seed(config.get_or<uint64_t>("seed", 0))));
  const Experiment experiment = Experiment::from_config(config);
  auto env = make_vec_env(experiment.env);
  auto algorithm = make_algorithm(experiment, *env);
  const auto start = std::chrono::steady_clock::now();
  algorithm->learn(experiment.n_timesteps);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto evaluation_env = make_evaluation_env(experiment.env, *env);
  const envs::RunResult result =
      testing::evaluate(algorithm->policy(), *evaluation_env, 10, experiment.seed + 1000);
  std::printf("ppo seed %llu, 30000 steps in %.1f s: return %.3f ± %.3f\n",
              static_cast<unsigned long long>(experiment.seed), seconds, result.mean_return(),
              result.std_return());
  EXPECT_GT(result.mean_return(), -2.5);

  // The slack tendons' return over the same episodes (episode k reset with seed + 1000 + k).
  double slack = 0.0;
  const auto robot = make_evaluation_env(experiment.env, *env);
  for (int k = 0; k < 10; ++k) {
    robot->reset(experiment.seed + 1000 + k);
    for (int t = 0; t < 50; ++t) slack += robot->step(Action::Zero(3)).reward / 10.0;
  }
  std::printf("slack tendons: return %.3f\n", slack);
  EXPECT_LT(slack, -5.0);
}

}  // namespace
}  // namespace tendril::rl
