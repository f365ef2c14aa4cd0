// The hand-written gradient of DQN's loss (dqn_loss over nn::DenseMlp) against LibTorch
// autograd of the same loss, written as Stable-Baselines3's DQN.train writes it with
// torch::nn::Linear layers, on the same batch and parameters.
#include "tendril/rl/dqn/dqn_loss.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include "support/tensor_views.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::rl {
namespace {

using testing::columns;

constexpr int64_t kObservationSize = 4;
constexpr int64_t kActions = 3;
constexpr int64_t kBatch = 64;
constexpr double kGamma = 0.99;
const std::vector<int64_t> kSizes{kObservationSize, 32, 32, kActions};

// SB3's QNetwork: Linear, ReLU, Linear, ReLU, Linear, its weights read from a flat vector in
// torch's parameter order (which is DenseMlp's layout); with `bounded`, a Tanh after the last
// Linear (the bounded head, scaled outside).
torch::nn::Sequential q_module(const Eigen::VectorXf& parameters, bool bounded = false) {
  torch::nn::Sequential module(torch::nn::Linear(kSizes[0], kSizes[1]), torch::nn::ReLU(),
                               torch::nn::Linear(kSizes[1], kSizes[2]), torch::nn::ReLU(),
                               torch::nn::Linear(kSizes[2], kSizes[3]));
  if (bounded) module->push_back(torch::nn::Tanh());
  torch::NoGradGuard no_grad;
  int64_t offset = 0;
  for (torch::Tensor& parameter : module->parameters()) {
    parameter.copy_(
        torch::from_blob(const_cast<float*>(parameters.data()) + offset, parameter.sizes()));
    offset += parameter.numel();
  }
  EXPECT_EQ(offset, parameters.size());
  return module;
}

Eigen::VectorXf flat_gradient(const torch::nn::Sequential& module) {
  std::vector<torch::Tensor> pieces;
  for (const torch::Tensor& parameter : module->parameters())
    pieces.push_back(parameter.grad().reshape({-1}));
  const torch::Tensor gradient = torch::cat(pieces);
  return Eigen::Map<const Eigen::VectorXf>(gradient.data_ptr<float>(), gradient.numel());
}

struct TorchBatch {
  torch::Tensor observations, actions, rewards, next_observations, terminated;
};

// Rewards spread widely enough that errors fall on both sides of the Huber kink; about a third
// of the transitions terminated.
TorchBatch random_batch(uint64_t seed) {
  torch::manual_seed(static_cast<int64_t>(seed));
  TorchBatch batch;
  batch.observations = torch::randn({kBatch, kObservationSize});
  batch.actions = torch::randint(kActions, {kBatch, 1}, torch::kLong);
  batch.rewards = 1.5 * torch::randn({kBatch, 1});
  batch.next_observations = torch::randn({kBatch, kObservationSize});
  batch.terminated = (torch::rand({kBatch, 1}) < 0.3).to(torch::kFloat);
  return batch;
}

ReplayBuffer::Batch to_replay_batch(const TorchBatch& batch) {
  ReplayBuffer::Batch result;
  result.observations = columns(batch.observations);
  result.actions = columns(batch.actions.to(torch::kFloat));
  result.rewards = columns(batch.rewards).transpose();
  result.next_observations = columns(batch.next_observations);
  result.terminated = columns(batch.terminated).transpose();
  return result;
}

struct AutogradResult {
  double loss = 0.0;
  Eigen::VectorXf gradient;
  double linear_fraction = 0.0;  // of errors beyond the Huber kink
};

// Stable-Baselines3's DQN.train: the target without gradient, Q(s, a) by gather, smooth L1
// averaged over the batch; double DQN picks a' with the online network. A positive q_bound B
// makes Q = B·tanh(z).
AutogradResult autograd_loss(const Eigen::VectorXf& parameters, const Eigen::VectorXf& target,
                             const TorchBatch& batch, bool double_q, double q_bound = 0.0) {
  const bool bounded = q_bound > 0.0;
  const double scale = bounded ? q_bound : 1.0;
  torch::nn::Sequential q = q_module(parameters, bounded);
  torch::nn::Sequential q_target = q_module(target, bounded);
  torch::Tensor target_values;
  {
    torch::NoGradGuard no_grad;
    const torch::Tensor next_q = scale * q_target->forward(batch.next_observations);
    const torch::Tensor next_values =
        double_q ? next_q.gather(1, q->forward(batch.next_observations).argmax(1, true))
                 : std::get<0>(next_q.max(1)).reshape({-1, 1});
    target_values = batch.rewards + (1 - batch.terminated) * kGamma * next_values;
  }
  const torch::Tensor current = scale * q->forward(batch.observations).gather(1, batch.actions);
  const torch::Tensor loss = torch::nn::functional::smooth_l1_loss(current, target_values);
  loss.backward();
  AutogradResult result;
  result.loss = loss.item<double>();
  result.gradient = flat_gradient(q);
  result.linear_fraction =
      ((current - target_values).abs() > 1).to(torch::kFloat).mean().item<double>();
  return result;
}

class DqnLossTest : public ::testing::TestWithParam<bool> {};

TEST_P(DqnLossTest, LossAndGradientMatchAutograd) {
  const bool double_q = GetParam();
  const nn::DenseMlp q_network(kSizes, nn::Activation::kRelu);
  Eigen::VectorXf parameters(q_network.parameter_count()), target(q_network.parameter_count());
  Rng rng(11);
  q_network.initialize(parameters, rng);
  q_network.initialize(target, rng);
  for (uint64_t seed : {1, 2, 3}) {
    const TorchBatch batch = random_batch(seed);
    const AutogradResult expected = autograd_loss(parameters, target, batch, double_q);
    // Both sides of the kink and both kinds of transition are exercised.
    ASSERT_GT(expected.linear_fraction, 0.2);
    ASSERT_LT(expected.linear_fraction, 0.8);
    ASSERT_GT(batch.terminated.sum().item<float>(), 5.0f);

    DqnLossWorkspace workspace;
    // dqn_loss adds to the gradient it is given.
    Eigen::VectorXf gradient = Eigen::VectorXf::Ones(q_network.parameter_count());
    const double loss = dqn_loss(q_network, parameters, target, to_replay_batch(batch), kGamma,
                                 double_q, /*q_bound=*/0.0, workspace, gradient);
    gradient.array() -= 1.0f;
    EXPECT_NEAR(loss, expected.loss, 1e-5 * expected.loss) << "batch " << seed;
    EXPECT_TRUE(gradient.isApprox(expected.gradient, 1e-4f))
        << "batch " << seed << ": relative error "
        << (gradient - expected.gradient).norm() / expected.gradient.norm();
  }
}

INSTANTIATE_TEST_SUITE_P(TargetChoice, DqnLossTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "DoubleQ" : "MaxOfTarget";
                         });

// The bounded head Q = B·tanh(z) of the thesis' limb critic: loss and gradient through the tanh
// and the scale, against autograd. B = 3 keeps the errors on both sides of the Huber kink.
TEST(DqnLoss, BoundedHeadMatchesAutograd) {
  constexpr double kBound = 3.0;
  const nn::DenseMlp q_network(kSizes, nn::Activation::kRelu, /*tanh_output=*/true);
  Eigen::VectorXf parameters(q_network.parameter_count()), target(q_network.parameter_count());
  Rng rng(13);
  q_network.initialize(parameters, rng);
  q_network.initialize(target, rng);
  for (bool double_q : {false, true}) {
    const TorchBatch batch = random_batch(7);
    const AutogradResult expected = autograd_loss(parameters, target, batch, double_q, kBound);
    ASSERT_GT(expected.linear_fraction, 0.2);
    ASSERT_LT(expected.linear_fraction, 0.8);
    DqnLossWorkspace workspace;
    Eigen::VectorXf gradient = Eigen::VectorXf::Zero(q_network.parameter_count());
    const double loss = dqn_loss(q_network, parameters, target, to_replay_batch(batch), kGamma,
                                 double_q, kBound, workspace, gradient);
    EXPECT_NEAR(loss, expected.loss, 1e-5 * expected.loss);
    EXPECT_TRUE(gradient.isApprox(expected.gradient, 1e-4f))
        << "relative error " << (gradient - expected.gradient).norm() / expected.gradient.norm();
  }
}

// With the online network picking a' where it disagrees with the target network, double DQN's
// targets — and so its loss — differ from DQN's.
TEST(DqnLoss, DoubleQChangesTheTargets) {
  const nn::DenseMlp q_network(kSizes, nn::Activation::kRelu);
  Eigen::VectorXf parameters(q_network.parameter_count()), target(q_network.parameter_count());
  Rng rng(5);
  q_network.initialize(parameters, rng);
  q_network.initialize(target, rng);
  const ReplayBuffer::Batch batch = to_replay_batch(random_batch(4));
  DqnLossWorkspace workspace;
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(q_network.parameter_count());
  const double dqn =
      dqn_loss(q_network, parameters, target, batch, kGamma, false, 0.0, workspace, gradient);
  const double double_dqn =
      dqn_loss(q_network, parameters, target, batch, kGamma, true, 0.0, workspace, gradient);
  EXPECT_GT(std::abs(dqn - double_dqn), 1e-4);
  // With the target network as the online one, the two coincide.
  const double same_dqn =
      dqn_loss(q_network, target, target, batch, kGamma, false, 0.0, workspace, gradient);
  const double same_double =
      dqn_loss(q_network, target, target, batch, kGamma, true, 0.0, workspace, gradient);
  EXPECT_DOUBLE_EQ(same_dqn, same_double);
}

}  // namespace
}  // namespace tendril::rl
