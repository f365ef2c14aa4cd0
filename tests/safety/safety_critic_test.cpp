#include "tendril/safety/safety_critic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/rl/dqn/dqn.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::safety {
namespace {

std::unique_ptr<envs::VecEnv> double_integrator(const std::string& params) {
  rl::VecEnvOptions options;
  options.id = "Safety/DoubleIntegrator-v0";
  options.params = Config::parse(params);
  return rl::make_vec_env(options);
}

std::filesystem::path temp_file(const std::string& name) {
  const auto directory = std::filesystem::temp_directory_path() / "tendril_safety_critic_test";
  std::filesystem::create_directories(directory);
  return directory / name;
}

const std::vector<Observation> kStates = {
    Eigen::Vector3f(0.0f, 0.0f, 0.0f), Eigen::Vector3f(1.9f, 2.8f, 0.5f),
    Eigen::Vector3f(-1.2f, -0.4f, 0.9f), Eigen::Vector3f(0.3f, -2.5f, 0.1f)};

TEST(SafetyCriticFile, SacCriticRoundTripsExactly) {
  auto env = double_integrator("horizon: 100");
  rl::Sac agent(*env, rl::SacConfig::from_config(Config::parse("net_arch: [16, 16]")), 4);
  const SacSafetyCritic critic(agent.policy(), agent.critics());
  const auto file = temp_file("sac.critic");
  critic.save(file);
  const auto loaded = load_safety_critic(file);
  for (const Observation& x : kStates) {
    EXPECT_TRUE(loaded->safe_action(x) == critic.safe_action(x));
    for (float a : {-2.0f, -0.5f, 1.3f}) {
      const Action u = Action::Constant(1, a);
      EXPECT_EQ(loaded->value(x, u), critic.value(x, u));
    }
    EXPECT_EQ(loaded->state_value(x), critic.state_value(x));
  }
}

// algo: the DQN keys; bound: the largest |Q| allowed (infinity: unbounded).
void expect_dqn_critic_round_trips(const std::string& algo, double bound) {
  auto env = double_integrator("discrete_actions: 5");
  rl::Dqn agent(*env, rl::DqnConfig::from_config(Config::parse(algo)), 9);
  const DqnSafetyCritic critic(dynamic_cast<const rl::QGreedyPolicy&>(agent.policy()));
  const auto file = temp_file("dqn.critic");
  critic.save(file);
  const auto loaded = load_safety_critic(file);
  for (const Observation& x : kStates) {
    EXPECT_EQ(loaded->safe_action(x)[0], critic.safe_action(x)[0]);
    for (int u = 0; u < 5; ++u) {
      const Action action = Action::Constant(1, static_cast<float>(u));
      EXPECT_EQ(loaded->value(x, action), critic.value(x, action));
      EXPECT_LT(std::abs(critic.value(x, action)), bound);
    }
  }
}

TEST(SafetyCriticFile, DqnCriticRoundTripsExactly) {
  expect_dqn_critic_round_trips("net_arch: [16, 16]", std::numeric_limits<double>::infinity());
}

// The thesis' limb critic ends in (1/(1 − γ))·tanh: the bound is part of the file.
TEST(SafetyCriticFile, BoundedDqnCriticRoundTripsWithItsBound) {
  expect_dqn_critic_round_trips("{net_arch: [16, 16], q_bound: 0.05}", 0.05);
}

TEST(SafetyCriticFile, CorruptOrForeignFilesAreRefusedNamingTheFile) {
  auto env = double_integrator("discrete_actions: 3");
  rl::Dqn agent(*env, rl::DqnConfig::from_config(Config::parse("net_arch: [8]")), 1);
  const auto file = temp_file("corrupt.critic");
  DqnSafetyCritic(dynamic_cast<const rl::QGreedyPolicy&>(agent.policy())).save(file);
  {
    std::fstream stream(file, std::ios::in | std::ios::out | std::ios::binary);
    stream.seekp(static_cast<std::streamoff>(std::filesystem::file_size(file) / 2));
    stream.put('\x5a');
  }
  try {
    load_safety_critic(file);
    FAIL() << "a corrupt file was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  // A policy file is not a safety critic file.
  const auto policy_file = temp_file("model.policy");
  agent.policy().save(policy_file);
  EXPECT_THROW(load_safety_critic(policy_file), Error);
}

}  // namespace
}  // namespace tendril::safety
