#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<envs::VecEnv> pendulum(int n_envs, bool normalize = false) {
  VecEnvOptions options;
  options.id = "Pendulum-v1";
  options.n_envs = n_envs;
  options.normalize_observation = normalize;
  options.normalize_reward = normalize;
  return make_vec_env(options);
}

const char* kSmallPpo = "n_steps: 128\nbatch_size: 64\nn_epochs: 3\n";

Eigen::VectorXf parameters_of(const OnPolicyAlgorithm& algorithm) {
  return algorithm.actor_critic().parameters();
}

bool same_parameters(const Eigen::VectorXf& a, const Eigen::VectorXf& b) { return a == b; }

envs::BatchMatrix probe_observations() {
  envs::BatchMatrix observations(8, 3);
  for (int i = 0; i < 8; ++i) {
    const double angle = 0.8 * i;
    observations.row(i) << std::cos(angle), std::sin(angle), 0.5f * (i - 4);
  }
  return observations;
}

class PpoReproducibility : public testing::ScratchDirectoryTest {
 protected:
  PpoReproducibility() : ScratchDirectoryTest("ppo_test") {}
};

TEST_F(PpoReproducibility, SameSeedGivesIdenticalReturnsAndParameters) {
  std::vector<std::vector<double>> returns;
  std::vector<Eigen::VectorXf> parameters;
  for (uint64_t seed : {7u, 7u, 8u}) {
    auto env = pendulum(2);
    Ppo ppo(*env, PpoConfig::from_config(Config::parse(kSmallPpo)), seed);
    std::vector<double> losses;
    ppo.learn(1024, [&](const Progress& progress) {
      for (const auto& [name, value] : progress.train) {
        if (name == "train/loss") losses.push_back(value);
      }
      return true;
    });
    EXPECT_EQ(ppo.num_timesteps(), 1024);
    EXPECT_EQ(ppo.recent_returns().size(), 4u);  // 2 envs × 512 steps / 200-step episodes
    std::vector<double> run(ppo.recent_returns().begin(), ppo.recent_returns().end());
    run.insert(run.end(), losses.begin(), losses.end());
    returns.push_back(run);
    parameters.push_back(parameters_of(ppo));
  }
  EXPECT_EQ(returns[0], returns[1]);
  EXPECT_TRUE(same_parameters(parameters[0], parameters[1]));
  EXPECT_NE(returns[0], returns[2]);
  EXPECT_FALSE(same_parameters(parameters[0], parameters[2]));
}

TEST_F(PpoReproducibility, SaveThenLoadGivesIdenticalActionsAndState) {
  const fs::path file = directory_ / "model.ckpt";
  auto env = pendulum(2, /*normalize=*/true);
  Ppo trained(*env, PpoConfig::from_config(Config::parse(kSmallPpo)), 3);
  trained.learn(512);
  trained.save(file);

  auto other_env = pendulum(2, /*normalize=*/true);
  Ppo restored(*other_env, PpoConfig::from_config(Config::parse(kSmallPpo)), 99);
  EXPECT_FALSE(same_parameters(parameters_of(trained), parameters_of(restored)));
  restored.load(file);
  EXPECT_TRUE(same_parameters(parameters_of(trained), parameters_of(restored)));
  EXPECT_EQ(restored.num_timesteps(), 512);
  EXPECT_EQ(restored.iterations(), trained.iterations());
  EXPECT_EQ(restored.recent_returns(), trained.recent_returns());

  const envs::BatchMatrix observations = probe_observations();
  EXPECT_EQ(trained.predict(observations, true), restored.predict(observations, true));
  // The prediction stream is restored too: stochastic actions match draw for draw.
  EXPECT_EQ(trained.predict(observations, false), restored.predict(observations, false));
  const Action single = trained.predict(Observation(observations.row(0).transpose()), true);
  EXPECT_EQ(single.size(), 1);
  EXPECT_LE(std::abs(single[0]), 2.0f);  // clipped to Pendulum's torque bounds
}

TEST_F(PpoReproducibility, CorruptOrMismatchedCheckpointRaisesAndChangesNothing) {
  const fs::path file = directory_ / "model.ckpt";
  auto env = pendulum(1);
  Ppo ppo(*env, PpoConfig::from_config(Config::parse(kSmallPpo)), 5);
  ppo.learn(256);
  ppo.save(file);
  std::ifstream in(file, std::ios::binary);
  const std::string bytes(std::istreambuf_iterator<char>(in), {});

  const fs::path truncated = directory_ / "truncated.ckpt";
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() - 100);

  auto fresh_env = pendulum(1);
  Ppo fresh(*fresh_env, PpoConfig::from_config(Config::parse(kSmallPpo)), 6);
  const auto before = parameters_of(fresh);
  const envs::BatchMatrix observations = probe_observations();
  const envs::BatchMatrix actions_before = fresh.predict(observations, true);
  EXPECT_THROW(fresh.load(truncated), Error);
  EXPECT_THROW(fresh.load(directory_ / "absent.ckpt"), Error);

  // A checkpoint of a different architecture is refused with a clear error.
  VecEnvOptions cartpole_options;
  cartpole_options.id = "CartPole-v1";
  auto cartpole = make_vec_env(cartpole_options);
  Ppo cartpole_ppo(*cartpole, PpoConfig::from_config(Config::parse(kSmallPpo)), 1);
  const fs::path cartpole_file = directory_ / "cartpole.ckpt";
  cartpole_ppo.save(cartpole_file);
  EXPECT_THROW(fresh.load(cartpole_file), Error);
  Ppo wide(*fresh_env, PpoConfig::from_config(Config::parse("policy: {net_arch: [32]}\n")), 1);
  EXPECT_THROW(wide.load(file), Error);

  EXPECT_TRUE(same_parameters(before, parameters_of(fresh)));
  EXPECT_EQ(fresh.predict(observations, true), actions_before);
  EXPECT_EQ(fresh.num_timesteps(), 0);

  // Saving into a directory that does not exist fails without touching the good file.
  EXPECT_THROW(ppo.save(directory_ / "missing" / "model.ckpt"), Error);
  std::ifstream again(file, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), bytes);
}

}  // namespace
}  // namespace tendril::rl
