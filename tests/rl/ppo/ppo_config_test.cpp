#include "tendril/rl/ppo/ppo_config.hpp"

#include <gtest/gtest.h>

#include "tendril/core/error.hpp"

namespace tendril::rl {
namespace {

TEST(PpoConfig, DefaultsAreStableBaselines3s) {
  const PpoConfig config = PpoConfig::from_config(Config::parse("{}"));
  EXPECT_EQ(config.common.n_steps, 2048);
  EXPECT_EQ(config.batch_size, 64);
  EXPECT_EQ(config.n_epochs, 10);
  EXPECT_DOUBLE_EQ(config.common.gamma, 0.99);
  EXPECT_DOUBLE_EQ(config.common.gae_lambda, 0.95);
  EXPECT_DOUBLE_EQ(config.clip_range.initial, 0.2);
  EXPECT_FALSE(config.clip_range.linear);
  EXPECT_FALSE(config.clip_range_vf.has_value());
  EXPECT_DOUBLE_EQ(config.ent_coef, 0.0);
  EXPECT_DOUBLE_EQ(config.vf_coef, 0.5);
  EXPECT_EQ(config.max_grad_norm, 0.5);
  EXPECT_DOUBLE_EQ(config.learning_rate.initial, 3e-4);
  EXPECT_FALSE(config.learning_rate.linear);
  EXPECT_FALSE(config.target_kl.has_value());
  EXPECT_TRUE(config.common.normalize_advantage);
  EXPECT_EQ(config.common.policy.policy_layers, (std::vector<int64_t>{64, 64}));
  EXPECT_EQ(config.common.policy.activation, nn::Activation::kTanh);
}

TEST(PpoConfig, Ppo1PresetIsStableBaselinesV2s) {
  const PpoConfig config = PpoConfig::from_config(Config::parse("preset: ppo1\n"));
  EXPECT_EQ(config.common.n_steps, 256);
  EXPECT_EQ(config.batch_size, 64);
  EXPECT_EQ(config.n_epochs, 4);
  EXPECT_DOUBLE_EQ(config.ent_coef, 0.01);
  EXPECT_DOUBLE_EQ(config.learning_rate.initial, 1e-3);
  EXPECT_TRUE(config.learning_rate.linear);
  EXPECT_TRUE(config.clip_range.linear);
  EXPECT_DOUBLE_EQ(config.adam_epsilon, 1e-5);
  EXPECT_DOUBLE_EQ(config.vf_coef, 1.0);
  EXPECT_FALSE(config.max_grad_norm.has_value());
}

TEST(PpoConfig, KeysOverrideThePreset) {
  const PpoConfig config = PpoConfig::from_config(Config::parse(R"(
preset: ppo1
n_steps: 1024
gamma: 0.9
learning_rate: 1e-3
learning_rate_schedule: constant
clip_range_vf: 0.3
max_grad_norm: 0.5
target_kl: none
policy: {net_arch: [32, 32], activation: relu}
)"));
  EXPECT_EQ(config.common.n_steps, 1024);
  EXPECT_DOUBLE_EQ(config.common.gamma, 0.9);
  EXPECT_FALSE(config.learning_rate.linear);
  EXPECT_EQ(config.clip_range_vf, 0.3);
  EXPECT_EQ(config.max_grad_norm, 0.5);
  EXPECT_FALSE(config.target_kl.has_value());
  EXPECT_EQ(config.common.policy.value_layers, (std::vector<int64_t>{32, 32}));
  EXPECT_EQ(config.common.policy.activation, nn::Activation::kRelu);
}

TEST(PpoConfig, UnknownKeysPresetsAndBadValuesAreNamed) {
  const auto message = [](const std::string& yaml) {
    try {
      PpoConfig::from_config(Config::parse(yaml, "exp.yaml"));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("n_stpes: 10\n"), "exp.yaml: unknown key 'n_stpes'");
  EXPECT_EQ(message("policy: {netarch: [8]}\n"), "exp.yaml: unknown key 'policy.netarch'");
  EXPECT_NE(message("preset: ppo2\n").find("unknown PPO preset 'ppo2'"), std::string::npos);
  EXPECT_NE(message("batch_size: 0\n").find("batch_size"), std::string::npos);
  EXPECT_NE(message("gamma: 1.5\n").find("gamma"), std::string::npos);
  EXPECT_NE(message("learning_rate: fast\n").find("learning_rate"), std::string::npos);
}

}  // namespace
}  // namespace tendril::rl
