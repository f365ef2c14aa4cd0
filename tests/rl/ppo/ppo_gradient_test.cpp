// The hand-written gradient of PPO's loss (nn::DenseActorCritic passes and ppo_loss) against
// LibTorch autograd of the same loss, written as SB3 writes it, on the same minibatch.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <string>

#include "support/torch_networks.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/actor_critic.hpp"
#include "tendril/rl/ppo/ppo_loss.hpp"
#include "tendril/rl/rollout_minibatches.hpp"

namespace tendril::rl {
namespace {

using testing::columns_of;
using testing::leaf;
using testing::TorchActorCritic;
using testing::vector_of;

constexpr int64_t kBatch = 48;

struct Minibatch {
  torch::Tensor observations, actions, old_log_probs, old_values, advantages, returns;
};

// Observations and actions at random; old log-probabilities and values perturbed from the
// current ones so that some ratios and values fall outside the clip ranges and some inside.
Minibatch random_minibatch(const nn::ActorCriticSpec& spec, const Eigen::VectorXf& parameters,
                           uint64_t seed) {
  torch::manual_seed(static_cast<int64_t>(seed));
  Minibatch batch;
  batch.observations = torch::randn({kBatch, spec.observation_size});
  batch.actions = spec.discrete ? torch::randint(spec.action_size, {kBatch, 1}).to(torch::kFloat)
                                : torch::randn({kBatch, spec.action_size});
  torch::NoGradGuard no_grad;
  const TorchActorCritic current(spec, leaf(parameters).detach(), batch.observations);
  batch.old_log_probs =
      current.log_prob(batch.actions, spec.discrete) + 0.3 * torch::randn({kBatch});
  batch.old_values = current.value + 0.4 * torch::randn({kBatch});
  batch.advantages = torch::randn({kBatch});
  batch.returns = current.value + torch::randn({kBatch});
  return batch;
}

// The loss as Stable-Baselines3's PPO.train computes it.
struct AutogradLoss {
  torch::Tensor policy, value, entropy, total;
  double approx_kl = 0.0, clip_fraction = 0.0;
};
AutogradLoss autograd_loss(const nn::ActorCriticSpec& spec, const torch::Tensor& theta,
                           const Minibatch& batch, const PpoLossSettings& settings) {
  const TorchActorCritic evaluation(spec, theta, batch.observations);
  const torch::Tensor log_ratio =
      evaluation.log_prob(batch.actions, spec.discrete) - batch.old_log_probs;
  const torch::Tensor ratio = torch::exp(log_ratio);
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
  loss.entropy = -evaluation.entropy(spec.discrete).mean();
  loss.total = loss.policy + settings.ent_coef * loss.entropy + settings.vf_coef * loss.value;
  // SB3's statistics: the approximate KL ((r − 1) − log r) averaged over the minibatch (Schulman's
  // k3 estimator) and the fraction of ratios outside the clip range.
  const torch::Tensor fixed_log_ratio = log_ratio.detach();
  loss.approx_kl = ((fixed_log_ratio.exp() - 1) - fixed_log_ratio).mean().item<double>();
  loss.clip_fraction =
      ((ratio.detach() - 1).abs() > settings.clip_range).to(torch::kDouble).mean().item<double>();
  return loss;
}

void expect_relatively_near(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-5 * std::abs(expected) + 1e-6) << what;
}

void check_gradient(const nn::ActorCriticSpec& spec, const PpoLossSettings& settings,
                    uint64_t seed) {
  const nn::ActorCritic network(spec);
  Eigen::VectorXf parameters(network.parameter_count());
  Rng init_rng(seed);
  network.initialize(parameters, init_rng);
  if (!spec.discrete) {  // σ away from 1, so that the log σ terms are not trivial
    parameters.segment(network.log_std_offset(), spec.action_size) =
        Eigen::VectorXf::LinSpaced(spec.action_size, -0.6f, 0.3f);
  }
  const Minibatch batch = random_minibatch(spec, parameters, seed);

  const torch::Tensor theta = leaf(parameters);
  const AutogradLoss expected = autograd_loss(spec, theta, batch, settings);
  expected.total.backward();
  const Eigen::VectorXf reference = vector_of(theta.grad());

  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(network.parameter_count());
  nn::ActorCritic::Tape tape;
  PpoSampleGradients sample_gradients;
  const Eigen::MatrixXf observations = columns_of(batch.observations);
  const Eigen::MatrixXf actions = columns_of(batch.actions);
  const Eigen::RowVectorXf old_log_probs = vector_of(batch.old_log_probs).transpose();
  const Eigen::RowVectorXf old_values = vector_of(batch.old_values).transpose();
  const Eigen::RowVectorXf advantages = vector_of(batch.advantages).transpose();
  const Eigen::RowVectorXf returns = vector_of(batch.returns).transpose();
  const RolloutMinibatch minibatch{observations, actions,    old_log_probs,
                                   old_values,   advantages, returns};
  network.evaluate(parameters, minibatch.observations, minibatch.actions, tape);
  const PpoLossTerms terms =
      ppo_loss(minibatch, tape.log_prob, tape.entropy, tape.value, settings, sample_gradients);
  network.backward(parameters, tape, sample_gradients.log_prob, sample_gradients.entropy,
                   sample_gradients.value, gradient);

  expect_relatively_near(terms.policy_loss, expected.policy.item<double>(), "policy loss");
  expect_relatively_near(terms.value_loss, expected.value.item<double>(), "value loss");
  expect_relatively_near(terms.entropy_loss, expected.entropy.item<double>(), "entropy loss");
  expect_relatively_near(terms.loss, expected.total.item<double>(), "loss");
  expect_relatively_near(terms.approx_kl, expected.approx_kl, "approximate KL");
  EXPECT_GT(terms.approx_kl, 0.0);
  EXPECT_DOUBLE_EQ(terms.clip_fraction, expected.clip_fraction);
  // Both branches of the clipped surrogate are exercised.
  EXPECT_GT(terms.clip_fraction, 0.1);
  EXPECT_LT(terms.clip_fraction, 0.9);

  // The policy block and the value block, each to a relative 1e-4 of its norm.
  const int64_t policy_count = network.policy_parameter_count();
  for (const auto& [name, offset, count] :
       {std::tuple<const char*, int64_t, int64_t>{"policy", 0, policy_count},
        {"value", policy_count, network.parameter_count() - policy_count}}) {
    const Eigen::VectorXf ours = gradient.segment(offset, count);
    const Eigen::VectorXf theirs = reference.segment(offset, count);
    EXPECT_GT(theirs.norm(), 0.0f) << name;
    EXPECT_LE((ours - theirs).norm(), 1e-4f * theirs.norm()) << name;
  }
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

TEST(PpoGradient, ASoftsignActorWithASoftsignMeanMatchesAutograd) {
  // Seed 002's actor: softsign in the trunk and on the Gaussian mean.
  nn::ActorCriticSpec spec = gaussian(false);
  spec.activation = nn::Activation::kSoftsign;
  spec.policy_output_activation = nn::Activation::kSoftsign;
  check_gradient(spec, kPlain, 11);
  check_gradient(spec, kClippedWithEntropy, 12);
  spec.shared_trunk = true;
  check_gradient(spec, kPlain, 13);
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
