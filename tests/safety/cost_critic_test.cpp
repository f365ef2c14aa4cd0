#include "tendril/safety/cost_critic.hpp"

#include <gtest/gtest.h>

#include "one_step.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::safety {
namespace {

std::unique_ptr<envs::VecEnv> double_integrator() {
  rl::VecEnvOptions options;
  options.id = "Safety/DoubleIntegrator-v0";
  return rl::make_vec_env(options);
}

// One step x → x' with action u (env units) and cost c.
void feed(CostCritic& critic, float x, float u, float next, float cost, int64_t timesteps) {
  testing::OneStep one(Eigen::Vector3f(x, 0.0f, 0.0f), Eigen::VectorXf::Constant(1, u),
                       Eigen::Vector3f(next, 0.0f, 0.0f));
  critic.on_step(one.info(info_keys::kCost, cost).event(timesteps));
}

// A two-step chain under every action: from x = 0 the next state is x = 1 (no cost), from x = 1
// every action violates the constraint (cost 1, the critic's episode ends). Then Q_risk(1, ·) = 1
// and Q_risk(0, ·) = γ_risk · 1, whatever the task policy's next action.
TEST(CostCritic, LearnsTheDiscountedProbabilityOfAViolationOnAChain) {
  auto env = double_integrator();
  rl::Sac task(*env, rl::SacConfig::from_config(Config::parse("net_arch: [16]")), 3);
  CostCriticSettings settings;
  settings.gamma = 0.8;
  settings.net_arch = {32, 32};
  settings.learning_rate = 1e-3;
  settings.batch_size = 64;
  settings.learning_starts = 64;
  settings.tau = 0.05;
  CostCritic critic(task.policy(), settings, 5);
  int64_t t = 0;
  for (int round = 0; round < 60; ++round) {
    for (int k = 0; k <= 20; ++k) {
      const float u = -2.0f + 0.2f * static_cast<float>(k);
      feed(critic, 0.0f, u, 1.0f, 0.0f, ++t);
      feed(critic, 1.0f, u, 2.5f, 1.0f, ++t);
    }
  }
  EXPECT_EQ(critic.buffer().size(), 60 * 42);
  EXPECT_TRUE(critic.buffer().terminated(1));
  EXPECT_FALSE(critic.buffer().terminated(0));
  Eigen::MatrixXf observations = Eigen::MatrixXf::Zero(3, 3);
  observations(0, 1) = 1.0f;
  Eigen::MatrixXf actions(1, 3);
  actions << -0.5f, 0.0f, 0.7f;  // in [−1, 1]
  observations(0, 2) = 1.0f;
  const Eigen::VectorXf values = critic.values(observations, actions);
  EXPECT_NEAR(values[0], 0.8, 0.08);
  EXPECT_NEAR(values[1], 1.0, 0.08);
  EXPECT_NEAR(values[2], 1.0, 0.08);
}

TEST(CostCritic, RefusesAnEnvironmentWithoutCostAndBadSettings) {
  auto env = double_integrator();
  rl::Sac task(*env, rl::SacConfig::from_config(Config::parse("net_arch: [16]")), 3);
  CostCritic critic(task.policy(), CostCriticSettings{}, 5);
  const testing::OneStep no_cost(Eigen::Vector3f::Zero(), Eigen::VectorXf::Zero(1),
                                 Eigen::Vector3f::Zero());
  EXPECT_THROW(critic.on_step(no_cost.event(1)), Error);
  EXPECT_THROW(CostCriticSettings::from_config(Config::parse("gamma: 1.0")), Error);
  EXPECT_THROW(CostCriticSettings::from_config(Config::parse("net_arch: []")), Error);
}

}  // namespace
}  // namespace tendril::safety
