// FlatParameters and FlatAdam against LibTorch's per-parameter utilities they replace.
#include "tendril/nn/flat_adam.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "tendril/core/error.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic.hpp"

namespace tendril::nn {
namespace {

ActorCritic pendulum_policy(uint64_t seed) {
  ActorCriticSpec spec;
  spec.observation_size = 3;
  spec.action_size = 1;
  Rng init_rng(seed);
  return ActorCritic(spec, init_rng);
}

// A loss touching every parameter: policy log-likelihood and value regression on fixed data.
torch::Tensor loss_of(ActorCritic& policy, int64_t round) {
  torch::manual_seed(round);
  const torch::Tensor observations = torch::randn({64, 3});
  const torch::Tensor actions = torch::randn({64, 1});
  const torch::Tensor returns = torch::randn({64});
  const auto evaluation = policy->evaluate(observations, actions);
  return -evaluation.log_prob.mean() + 0.5 * (returns - evaluation.value).pow(2).mean();
}

void expect_same(const std::vector<torch::Tensor>& a, const std::vector<torch::Tensor>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(torch::equal(a[i], b[i])) << i;
}

// Equal up to float rounding: the same formula evaluated by other kernels (fused or not).
void expect_close(const std::vector<torch::Tensor>& a, const std::vector<torch::Tensor>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(torch::allclose(a[i], b[i], /*rtol=*/1e-6, /*atol=*/1e-7)) << i;
  }
}

TEST(FlatParameters, ParametersAndGradientsBecomeViewsOfOneBuffer) {
  ActorCritic policy = pendulum_policy(1);
  std::vector<torch::Tensor> before;
  for (const auto& p : policy->parameters()) before.push_back(p.detach().clone());
  FlatParameters flat(policy->parameters());

  // Values unchanged, and the module's own parameters now read the flat buffer.
  expect_same(before, policy->parameters());
  EXPECT_EQ(flat.numel(), 2 * (3 * 64 + 64 + 64 * 64 + 64) + 65 + 65 + 1);
  {
    torch::NoGradGuard no_grad;
    flat.values().zero_();
  }
  for (const auto& p : policy->parameters()) EXPECT_EQ(p.abs().max().item<float>(), 0.0f);

  // Backward accumulates into the flat gradient buffer.
  loss_of(policy, 0).backward();
  EXPECT_GT(flat.gradients().abs().max().item<float>(), 0.0f);
  int64_t offset = 0;
  for (const auto& p : policy->parameters()) {
    EXPECT_TRUE(torch::equal(p.grad().reshape({-1}),
                             flat.gradients().slice(0, offset, offset + p.numel())));
    offset += p.numel();
  }
  flat.zero_grad();
  for (const auto& p : policy->parameters()) EXPECT_EQ(p.grad().abs().max().item<float>(), 0.0f);
}

TEST(FlatParameters, ClipsTheGlobalNormAsLibTorch) {
  ActorCritic reference = pendulum_policy(2);
  ActorCritic flat_policy = pendulum_policy(2);
  FlatParameters flat(flat_policy->parameters());
  for (double max_norm : {0.01, 1e6}) {
    for (auto* module : {&reference, &flat_policy}) {
      for (auto& p : (*module)->parameters()) {
        if (p.grad().defined()) p.mutable_grad().zero_();
      }
      loss_of(*module, 3).backward();
    }
    const double expected = torch::nn::utils::clip_grad_norm_(reference->parameters(), max_norm);
    EXPECT_NEAR(flat.clip_grad_norm(max_norm), expected, 1e-5 * expected);
    const auto clipped = reference->parameters();
    const auto ours = flat_policy->parameters();
    for (std::size_t i = 0; i < clipped.size(); ++i) {
      EXPECT_TRUE(torch::allclose(ours[i].grad(), clipped[i].grad(), 1e-5, 1e-9)) << i;
    }
  }
}

TEST(FlatAdam, StepsAsTorchAdam) {
  ActorCritic reference = pendulum_policy(4);
  ActorCritic flat_policy = pendulum_policy(4);
  torch::optim::Adam torch_adam(reference->parameters(), torch::optim::AdamOptions(3e-4).eps(1e-5));
  FlatAdam adam(flat_policy->parameters(), {.learning_rate = 3e-4, .epsilon = 1e-5});
  for (int64_t round = 0; round < 20; ++round) {
    if (round == 10) {
      static_cast<torch::optim::AdamOptions&>(torch_adam.param_groups()[0].options()).lr(1e-3);
      adam.set_learning_rate(1e-3);
    }
    torch_adam.zero_grad();
    loss_of(reference, round).backward();
    torch_adam.step();
    adam.zero_grad();
    loss_of(flat_policy, round).backward();
    adam.step();
    expect_close(reference->parameters(), flat_policy->parameters());
  }
  EXPECT_EQ(adam.steps(), 20);
}

TEST(FlatAdam, StateRoundTripsThroughAnArchive) {
  ActorCritic uninterrupted = pendulum_policy(5);
  FlatAdam adam(uninterrupted->parameters(), {.learning_rate = 1e-3, .epsilon = 1e-5});
  for (int64_t round = 0; round < 3; ++round) {
    adam.zero_grad();
    loss_of(uninterrupted, round).backward();
    adam.step();
  }
  std::stringstream bytes;
  {
    torch::serialize::OutputArchive archive;
    adam.save(archive);
    archive.save_to(bytes);
  }
  ActorCritic resumed = pendulum_policy(6);
  {
    torch::NoGradGuard no_grad;
    const auto source = uninterrupted->parameters();
    const auto target = resumed->parameters();
    for (std::size_t i = 0; i < source.size(); ++i) target[i].copy_(source[i]);
  }
  FlatAdam restored(resumed->parameters(), {.learning_rate = 1e-3, .epsilon = 1e-5});
  {
    torch::serialize::InputArchive archive;
    archive.load_from(bytes);
    restored.load(archive);
  }
  EXPECT_EQ(restored.steps(), 3);
  for (int64_t round = 3; round < 6; ++round) {
    for (auto* optimizer : {&adam, &restored}) optimizer->zero_grad();
    loss_of(uninterrupted, round).backward();
    loss_of(resumed, round).backward();
    adam.step();
    restored.step();
  }
  expect_same(uninterrupted->parameters(), resumed->parameters());

  // Moments of another network's size are refused.
  ActorCriticSpec small;
  small.observation_size = 3;
  small.action_size = 1;
  small.policy_layers = small.value_layers = {8};
  Rng init_rng(0);
  ActorCritic other(small, init_rng);
  FlatAdam mismatched(other->parameters(), {});
  bytes.seekg(0);
  torch::serialize::InputArchive archive;
  archive.load_from(bytes);
  EXPECT_THROW(mismatched.load(archive), Error);
}

}  // namespace
}  // namespace tendril::nn
