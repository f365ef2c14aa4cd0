#include "tendril/nn/actor_critic.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tendril/core/error.hpp"

namespace tendril::nn {
namespace {

ActorCriticSpec gaussian_spec(bool shared) {
  ActorCriticSpec spec = ActorCriticSpec{}.with_spaces(Space::box(3, -1, 1), Space::box(2, -2, 2));
  spec.shared_trunk = shared;
  return spec;
}

TEST(ActorCriticSpec, DefaultsAreSb3AndConfigOverrides) {
  const ActorCriticSpec defaults =
      ActorCriticSpec{}.with_spaces(Space::box(4, -1, 1), Space::discrete(3));
  EXPECT_EQ(defaults.policy_layers, (std::vector<int64_t>{64, 64}));
  EXPECT_EQ(defaults.value_layers, (std::vector<int64_t>{64, 64}));
  EXPECT_EQ(defaults.activation, Activation::kTanh);
  EXPECT_TRUE(defaults.orthogonal_init);
  EXPECT_FALSE(defaults.shared_trunk);
  EXPECT_TRUE(defaults.discrete);
  EXPECT_EQ(defaults.action_size, 3);
  EXPECT_EQ(defaults.observation_size, 4);

  const Config config = Config::parse(
      "policy: {net_arch: [32], vf_layers: [16, 16], activation: relu, log_std_init: -0.5}\n");
  const ActorCriticSpec spec = ActorCriticSpec::from_config(config.child("policy"));
  EXPECT_EQ(spec.policy_layers, (std::vector<int64_t>{32}));
  EXPECT_EQ(spec.value_layers, (std::vector<int64_t>{16, 16}));
  EXPECT_EQ(spec.activation, Activation::kRelu);
  EXPECT_DOUBLE_EQ(spec.log_std_init, -0.5);
  EXPECT_NO_THROW(config.reject_unknown());

  EXPECT_THROW(ActorCriticSpec::from_config(Config::parse("activation: sigmoid\n")), Error);
  EXPECT_THROW(ActorCriticSpec::from_config(Config::parse("net_arch: [64, 0]\n")), Error);
  const Config typo = Config::parse("policy: {net_arhc: [8]}\n");
  ActorCriticSpec::from_config(typo.child("policy"));
  EXPECT_THROW(typo.reject_unknown(), Error);
}

TEST(ActorCritic, GaussianEvaluateShapesAndInitialPolicy) {
  Rng rng(5);
  ActorCritic model(gaussian_spec(false), rng);
  const torch::Tensor observations = torch::randn({7, 3});
  const torch::Tensor actions = torch::randn({7, 2});
  const auto evaluation = model->evaluate(observations, actions);
  EXPECT_EQ(evaluation.log_prob.sizes(), (std::vector<int64_t>{7}));
  EXPECT_EQ(evaluation.entropy.sizes(), (std::vector<int64_t>{7}));
  EXPECT_EQ(evaluation.value.sizes(), (std::vector<int64_t>{7}));
  // The 0.01-gain policy head starts near zero mean; log σ starts at log_std_init = 0.
  const PolicyDistribution pi = model->distribution(observations);
  EXPECT_LT(pi.mean.abs().max().item<float>(), 0.1f);
  EXPECT_EQ(pi.log_std.abs().max().item<float>(), 0.0f);
  EXPECT_TRUE(torch::allclose(model->value(observations), evaluation.value));
  EXPECT_TRUE(torch::allclose(pi.log_prob(actions), evaluation.log_prob));
}

TEST(ActorCritic, PolicyAndValueParametersPartitionTheModule) {
  for (bool shared : {false, true}) {
    Rng rng(2);
    ActorCritic model(gaussian_spec(shared), rng);
    std::set<const void*> policy, value;
    for (const auto& p : model->policy_parameters()) policy.insert(p.unsafeGetTensorImpl());
    for (const auto& p : model->value_parameters()) value.insert(p.unsafeGetTensorImpl());
    for (const void* p : policy) EXPECT_EQ(value.count(p), 0u);
    EXPECT_EQ(policy.size() + value.size(), model->parameters().size());
    // Separate trunks: 2 policy layers + head + log σ = 7 tensors; shared: the value side is
    // only its head.
    EXPECT_EQ(policy.size(), 7u);
    EXPECT_EQ(value.size(), shared ? 2u : 6u);
  }
}

TEST(ActorCritic, CategoricalModeAndGradientsFlow) {
  Rng rng(9);
  ActorCriticSpec spec = ActorCriticSpec{}.with_spaces(Space::box(4, -1, 1), Space::discrete(5));
  ActorCritic model(spec, rng);
  const torch::Tensor observations = torch::randn({6, 4});
  const PolicyDistribution pi = model->distribution(observations);
  EXPECT_EQ(pi.logits.sizes(), (std::vector<int64_t>{6, 5}));
  const torch::Tensor mode = pi.mode();
  EXPECT_EQ(mode.sizes(), (std::vector<int64_t>{6, 1}));
  EXPECT_TRUE(torch::equal(mode.squeeze(-1).to(torch::kLong), pi.logits.argmax(-1)));
  const auto evaluation = model->evaluate(observations, mode);
  (evaluation.log_prob.sum() + evaluation.value.sum()).backward();
  for (const auto& p : model->parameters()) EXPECT_TRUE(p.grad().defined());
}

TEST(ActorCritic, SameSeedSameParameters) {
  Rng a(11), b(11);
  ActorCritic first(gaussian_spec(false), a), second(gaussian_spec(false), b);
  const auto p = first->parameters();
  const auto q = second->parameters();
  ASSERT_EQ(p.size(), q.size());
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_TRUE(torch::equal(p[i], q[i]));
}

}  // namespace
}  // namespace tendril::nn
