#include "tendril/safety/lagrangian_penalty.hpp"

#include <gtest/gtest.h>

#include "one_step.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/info_keys.hpp"
#include "tendril/rl/sac/sac.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::safety {
namespace {

struct Fixture {
  std::unique_ptr<envs::VecEnv> env;
  std::unique_ptr<rl::Sac> task;
  std::unique_ptr<CostCritic> critic;

  Fixture() {
    rl::VecEnvOptions options;
    options.id = "Safety/DoubleIntegrator-v0";
    env = rl::make_vec_env(options);
    task = std::make_unique<rl::Sac>(
        *env, rl::SacConfig::from_config(Config::parse("net_arch: [16]")), 3);
    CostCriticSettings settings;
    settings.net_arch = {16, 16};
    settings.learning_starts = 32;
    settings.batch_size = 32;
    settings.learning_rate = 3e-3;
    critic = std::make_unique<CostCritic>(task->policy(), settings, 5);
  }

  // Transitions from random states whose cost is always `cost` (terminal when 1).
  void train_constant_cost(float cost, int steps) {
    Rng rng(9);
    for (int t = 1; t <= steps; ++t) {
      Eigen::Vector3f x;
      x << static_cast<float>(rng.uniform(-2, 2)), static_cast<float>(rng.uniform(-3, 3)), 0.0f;
      const auto u = static_cast<float>(rng.uniform(-2, 2));
      testing::OneStep one(x, Eigen::VectorXf::Constant(1, u), x);
      critic->on_step(one.info(info_keys::kCost, cost).event(t));
    }
  }
};

Eigen::MatrixXf batch_observations() {
  Eigen::MatrixXf observations(3, 4);
  observations << 0.5f, -1.0f, 1.5f, 0.0f, 1.0f, 2.0f, -2.0f, 0.3f, 0.0f, 0.1f, 0.2f, 0.3f;
  return observations;
}

TEST(LagrangianPenalty, RspoAnnealsTheMultiplierLinearly) {
  Fixture f;
  MultiplierSettings settings;
  settings.kind = MultiplierSettings::Kind::kScheduled;
  settings.start = 100.0;
  settings.end = 20.0;
  LagrangianPenalty penalty(*f.critic, 0.1, settings, 1000);
  EXPECT_DOUBLE_EQ(penalty.multiplier(), 100.0);
  const testing::OneStep one(Eigen::Vector3f::Zero(), Eigen::VectorXf::Zero(1),
                             Eigen::Vector3f::Zero());
  penalty.on_step(one.event(250));
  EXPECT_DOUBLE_EQ(penalty.multiplier(), 80.0);
  penalty.on_step(one.event(1000));
  EXPECT_DOUBLE_EQ(penalty.multiplier(), 20.0);
  penalty.on_step(one.event(5000));  // past the budget: held at the end
  EXPECT_DOUBLE_EQ(penalty.multiplier(), 20.0);
}

// The actor's gradient is ν/B · ∂Q_risk/∂a, checked against central differences of the critic,
// and the returned term is ν (E[Q_risk] − ε).
TEST(LagrangianPenalty, GradientIsTheMultiplierTimesTheCriticsActionGradient) {
  Fixture f;
  f.train_constant_cost(1.0f, 200);  // any trained critic will do
  MultiplierSettings settings;
  settings.kind = MultiplierSettings::Kind::kScheduled;
  settings.start = settings.end = 7.0;
  LagrangianPenalty penalty(*f.critic, 0.25, settings, 1000);
  const Eigen::MatrixXf observations = batch_observations();
  Eigen::MatrixXf actions(1, 4);
  actions << -0.6f, 0.1f, 0.4f, 0.9f;
  Eigen::MatrixXf gradient = Eigen::MatrixXf::Ones(1, 4);  // added to, not overwritten
  const double term = penalty.add_gradient(observations, actions, gradient);
  const Eigen::VectorXf values = f.critic->values(observations, actions);
  EXPECT_NEAR(term, 7.0 * (values.mean() - 0.25), 1e-5);
  const float h = 1e-3f;  // small beside the ReLU critic's kinks
  for (int j = 0; j < 4; ++j) {
    Eigen::MatrixXf up = actions, down = actions;
    up(0, j) += h;
    down(0, j) -= h;
    const double slope =
        (f.critic->values(observations, up)[j] - f.critic->values(observations, down)[j]) / (2 * h);
    EXPECT_NEAR(gradient(0, j) - 1.0f, 7.0 / 4.0 * slope, 2e-3) << j;
  }
}

// Lagrangian relaxation: ν grows while the policy's risk exceeds the cost limit and shrinks
// while it stays below.
TEST(LagrangianPenalty, LearnedMultiplierFollowsTheConstraint) {
  for (const float cost : {1.0f, 0.0f}) {
    Fixture f;
    f.train_constant_cost(cost, 400);
    MultiplierSettings settings;
    settings.initial = 2.0;
    settings.learning_rate = 0.01;
    LagrangianPenalty penalty(*f.critic, 0.5, settings, 1000);
    Eigen::MatrixXf actions = Eigen::MatrixXf::Zero(1, 4);
    for (int k = 0; k < 50; ++k) {
      Eigen::MatrixXf gradient = Eigen::MatrixXf::Zero(1, 4);
      penalty.add_gradient(batch_observations(), actions, gradient);
    }
    if (cost > 0.5f) {
      EXPECT_GT(penalty.last_cost_value(), 0.5);
      EXPECT_GT(penalty.multiplier(), 2.0 * std::exp(0.4));
    } else {
      EXPECT_LT(penalty.last_cost_value(), 0.5);
      EXPECT_LT(penalty.multiplier(), 2.0 * std::exp(-0.4));
    }
  }
}

TEST(LagrangianPenalty, SettingsAreChecked) {
  EXPECT_THROW(MultiplierSettings::from_config("ppo", Config::parse("{}")), Error);
  EXPECT_THROW(MultiplierSettings::from_config("lagrangian", Config::parse("initial: 0")), Error);
  EXPECT_THROW(MultiplierSettings::from_config("rspo", Config::parse("start: -1")), Error);
  const MultiplierSettings rspo =
      MultiplierSettings::from_config("rspo", Config::parse("start: 50"));
  EXPECT_EQ(rspo.kind, MultiplierSettings::Kind::kScheduled);
  EXPECT_DOUBLE_EQ(rspo.start, 50.0);
  EXPECT_DOUBLE_EQ(rspo.end, 0.0);
}

}  // namespace
}  // namespace tendril::safety
