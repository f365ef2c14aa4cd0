// The hand-written gradient of PPO's loss (nn::DenseActorCritic passes and ppo_loss) against
// LibTorch autograd of the same loss, written as SB3 writes it, on the same minibatch.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <string>

#include "support/tensor_views.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/dense_actor_critic.hpp"
#include "tendril/nn/flat_parameters.hpp"
#include "tendril/rl/ppo/ppo_loss.hpp"

namespace tendril::rl {
namespace {

using testing::columns;
using testing::row;

constexpr int64_t kBatch = 48;

struct Minibatch {
  torch::Tensor observations, actions, old_log_probs, old_values, advantages, returns;
};

// Observations and actions at random; old log-probabilities and values perturbed from the
// current ones so that some ratios and values fall outside the clip ranges and some inside.
Minibatch random_minibatch(nn::ActorCritic& policy, uint64_t seed) {
  const nn::ActorCriticSpec& spec = policy->spec();
  torch::manual_seed(static_cast<int64_t>(seed));
  Minibatch batch;
  batch.observations = torch::randn({kBatch, spec.observation_size});
  batch.actions = spec.discrete ? torch::randint(spec.action_size, {kBatch, 1}).to(torch::kFloat)
                                : torch::randn({kBatch, spec.action_size});
  torch::NoGradGuard no_grad;
  const auto current = policy->evaluate(batch.observations, batch.actions);
  batch.old_log_probs = current.log_prob + 0.3 * torch::randn({kBatch});
  batch.old_values = current.value + 0.4 * torch::randn({kBatch});
  batch.advantages = torch::randn({kBatch});
  batch.returns = current.value + torch::randn({kBatch});
  return batch;
}

// The loss as Stable-Baselines3's PPO.train computes it.
struct AutogradLoss {
  torch::Tensor policy, value, entropy, total;
};
AutogradLoss autograd_loss(nn::ActorCritic& policy, const Minibatch& batch,
                           const PpoLossSettings& settings) {
  const auto evaluation = policy->evaluate(batch.observations, batch.actions);
  const torch::Tensor ratio = torch::exp(evaluation.log_prob - batch.old_log_probs);
  const torch::Tensor surrogate = torch::min(
      ratio * batch.advantages,
      torch::clamp(ratio, 1.0 - settings.clip_range, 1.0 + settings.clip_range) * batch.advantages);
  AutogradLoss loss;
  loss.policy = -surrogate.mean();
  torch::Tensor predicted = evaluation.value;
  if (settings.clip_range_vf) {
    const double clip = *settings.clip_range_vf;
    predicted = batch.old_values + torch::clamp(evaluation.value - batch.old_values, -clip, clip);
  }
  loss.value = torch::mse_loss(predicted, batch.returns);
  loss.entropy = -evaluation.entropy.mean();
  loss.total = loss.policy + settings.ent_coef * loss.entropy + settings.vf_coef * loss.value;
  return loss;
}

void expect_relatively_near(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-5 * std::abs(expected) + 1e-6) << what;
}

void check_gradient(const nn::ActorCriticSpec& spec, const PpoLossSettings& settings,
                    uint64_t seed) {
  Rng init_rng(seed);
  nn::ActorCritic policy(spec, init_rng);
  nn::FlatParameters flat(policy->parameters());
  if (!spec.discrete) {
    torch::NoGradGuard no_grad;  // σ away from 1, so that the log σ terms are not trivial
    policy->log_std().copy_(torch::linspace(-0.6, 0.3, spec.action_size));
  }
  const Minibatch batch = random_minibatch(policy, seed);

  flat.zero_grad();
  const AutogradLoss expected = autograd_loss(policy, batch, settings);
  expected.total.backward();
  const torch::Tensor expected_gradient = flat.gradients().clone();

  const nn::DenseActorCritic network(*policy, flat);
  const Eigen::Map<const Eigen::VectorXf> parameters(flat.values().data_ptr<float>(), flat.numel());
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(flat.numel());
  nn::DenseActorCritic::Tape tape;
  PpoSampleGradients sample_gradients;
  const PpoMinibatch minibatch{columns(batch.observations), columns(batch.actions),
                               row(batch.old_log_probs),    row(batch.old_values),
                               row(batch.advantages),       row(batch.returns)};
  network.evaluate(parameters, minibatch.observations, minibatch.actions, tape);
  const PpoLossTerms terms =
      ppo_loss(minibatch, tape.log_prob, tape.entropy, tape.value, settings, sample_gradients);
  network.backward(parameters, tape, sample_gradients.log_prob, sample_gradients.entropy,
                   sample_gradients.value, gradient);

  expect_relatively_near(terms.policy_loss, expected.policy.item<double>(), "policy loss");
  expect_relatively_near(terms.value_loss, expected.value.item<double>(), "value loss");
  expect_relatively_near(terms.entropy_loss, expected.entropy.item<double>(), "entropy loss");
  expect_relatively_near(terms.loss, expected.total.item<double>(), "loss");
  // Both branches of the clipped surrogate are exercised.
  EXPECT_GT(terms.clip_fraction, 0.1);
  EXPECT_LT(terms.clip_fraction, 0.9);

  // Every parameter tensor's gradient, to a relative 1e-4 of its norm.
  const Eigen::Map<const Eigen::VectorXf> reference(expected_gradient.data_ptr<float>(),
                                                    expected_gradient.numel());
  int64_t offset = 0;
  for (const auto& named : policy->named_parameters()) {
    const int64_t n = named.value().numel();
    const Eigen::VectorXf ours = gradient.segment(offset, n);
    const Eigen::VectorXf theirs = reference.segment(offset, n);
    EXPECT_GT(theirs.norm(), 0.0f) << named.key();
    EXPECT_LE((ours - theirs).norm(), 1e-4f * theirs.norm()) << named.key();
    offset += n;
  }
  EXPECT_EQ(offset, flat.numel());
}

nn::ActorCriticSpec gaussian(bool shared_trunk) {
  nn::ActorCriticSpec spec;
  spec.observation_size = 3;
  spec.action_size = 2;
  spec.shared_trunk = shared_trunk;
  return spec;
}

nn::ActorCriticSpec categorical(bool shared_trunk) {
  nn::ActorCriticSpec spec;
  spec.observation_size = 4;
  spec.discrete = true;
  spec.action_size = 3;
  spec.shared_trunk = shared_trunk;
  spec.activation = nn::Activation::kRelu;
  spec.policy_layers = {32, 16};
  spec.value_layers = {24};
  return spec;
}

// SB3's defaults: no value clipping, no entropy term.
const PpoLossSettings kPlain{
    .clip_range = 0.2, .clip_range_vf = std::nullopt, .ent_coef = 0.0, .vf_coef = 0.5};
// Value clipping and an entropy bonus.
const PpoLossSettings kClippedWithEntropy{
    .clip_range = 0.1, .clip_range_vf = 0.2, .ent_coef = 0.05, .vf_coef = 0.8};

TEST(PpoGradient, GaussianSeparateTrunksMatchesAutograd) {
  check_gradient(gaussian(false), kPlain, 1);
  check_gradient(gaussian(false), kClippedWithEntropy, 2);
}

TEST(PpoGradient, GaussianSharedTrunkMatchesAutograd) {
  check_gradient(gaussian(true), kPlain, 3);
  check_gradient(gaussian(true), kClippedWithEntropy, 4);
}

TEST(PpoGradient, CategoricalMatchesAutograd) {
  check_gradient(categorical(false), kPlain, 5);
  check_gradient(categorical(false), kClippedWithEntropy, 6);
  check_gradient(categorical(true), kPlain, 7);
  check_gradient(categorical(true), kClippedWithEntropy, 8);
}

TEST(PpoGradient, HeadsDirectlyOnTheObservationMatchAutograd) {
  // net_arch: [] — no trunk, each head is one linear layer on the observation.
  nn::ActorCriticSpec spec = gaussian(false);
  spec.policy_layers = spec.value_layers = {};
  check_gradient(spec, kClippedWithEntropy, 9);
  spec.shared_trunk = true;
  check_gradient(spec, kPlain, 10);
}

}  // namespace
}  // namespace tendril::rl
