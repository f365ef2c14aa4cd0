// A policy written out as a plain feed-forward computation (what the C and ONNX exports are
// made of) acts as the policy does, for every kind of policy.
#include "tendril/rl/export/policy_network.hpp"

#include <gtest/gtest.h>

#include "rl/export/sample_policies.hpp"
#include "support/error_message.hpp"
#include "tendril/nn/mlp_head.hpp"

namespace tendril::rl {
namespace {

using testing::sample_observations;
using testing::sample_policies;

// The network, evaluated one observation at a time in plain float loops, against Policy::act on
// the batch (BLAS products, Eigen's vectorised tanh): they differ by float rounding only —
// within 2e-5 of the action's range for 500 observations, most of them far enough out that the
// normalization's clip and the squashes act. Discrete actions are the same index (no two outputs
// of these random networks come within rounding of each other).
TEST(PolicyNetwork, ActsAsThePolicyForEveryKind) {
  for (const auto& [name, policy] : sample_policies()) {
    const PolicyNetwork network = policy_network(*policy);
    EXPECT_EQ(network.kind, policy->kind()) << name;
    EXPECT_EQ(network.mean.empty(), !policy->observation_normalization().has_value()) << name;
    const Eigen::MatrixXf observations =
        sample_observations(500, policy->observation_space().size(), 11);
    Rng rng(0);
    envs::BatchMatrix actions;
    policy->act(observations, /*deterministic=*/true, rng, actions);
    int clipped = 0;
    for (Eigen::Index i = 0; i < observations.rows(); ++i) {
      const Action ours = evaluate_policy_network(network, observations.row(i).transpose());
      ASSERT_EQ(ours.size(), actions.cols()) << name;
      if (policy->action_space().is_discrete()) {
        EXPECT_EQ(ours[0], actions(i, 0)) << name << " observation " << i;
        continue;
      }
      const Space& space = policy->action_space();
      for (Eigen::Index j = 0; j < ours.size(); ++j) {
        const float range = space.high()[j] - space.low()[j];
        EXPECT_NEAR(ours[j], actions(i, j), 2e-5f * range) << name << " observation " << i;
        clipped += ours[j] == space.low()[j] || ours[j] == space.high()[j];
      }
    }
    // The PPO policies' means leave the box for some observations (the clip is exercised).
    if (name == "ppo_gaussian") {
      EXPECT_GT(clipped, 10) << name;
    }
  }
}

TEST(PolicyNetwork, KeepsOnlyTheRowsTheActionReads) {
  for (const auto& [name, policy] : sample_policies()) {
    const PolicyNetwork network = policy_network(*policy);
    const int64_t expected = policy->action_space().is_discrete() ? policy->action_space().n()
                                                                  : policy->action_space().size();
    EXPECT_EQ(network.layers.back().outputs, expected) << name;  // SAC: μ without log σ
    for (const PolicyNetwork::Layer& layer : network.layers) {
      EXPECT_EQ(static_cast<int64_t>(layer.weight.size()), layer.inputs * layer.outputs) << name;
      EXPECT_EQ(static_cast<int64_t>(layer.bias.size()), layer.outputs) << name;
    }
  }
}

TEST(PolicyNetwork, RefusesAPolicyWithAHistoryHead) {
  const Space observations = Space::box(12, -1.0f, 1.0f);
  auto head = std::make_shared<nn::MlpHead>(nn::DenseMlp({8, 4}, nn::Activation::kRelu));
  const SquashedGaussianPolicy policy(observations, Space::box(2, -1.0f, 1.0f), {16},
                                      nn::Activation::kRelu, false, head);
  EXPECT_NE(testing::error_message([&] { policy_network(policy); }).find("history head"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::rl
