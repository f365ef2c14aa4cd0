// The hand-written actor-critic passes against the LibTorch module they read in place.
#include "tendril/nn/dense_actor_critic.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "support/tensor_views.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::nn {
namespace {

using testing::columns;
using testing::row;

constexpr int64_t kBatch = 20;

// evaluate() equals ActorCritic::evaluate, and backward() of per-sample weights w equals
// autograd of Σ_t (w_logπ log π_t + w_H H_t + w_V V_t).
void check_against_module(const ActorCriticSpec& spec) {
  Rng init_rng(11);
  ActorCritic policy(spec, init_rng);
  FlatParameters flat(policy->parameters());
  torch::manual_seed(3);
  const torch::Tensor observations = torch::randn({kBatch, spec.observation_size});
  const torch::Tensor actions =
      spec.discrete ? torch::randint(spec.action_size, {kBatch, 1}).to(torch::kFloat)
                    : torch::randn({kBatch, spec.action_size});
  const torch::Tensor log_prob_weight = torch::randn({kBatch});
  const torch::Tensor entropy_weight = torch::randn({kBatch});
  const torch::Tensor value_weight = torch::randn({kBatch});

  const auto expected = policy->evaluate(observations, actions);
  ((expected.log_prob * log_prob_weight).sum() + (expected.entropy * entropy_weight).sum() +
   (expected.value * value_weight).sum())
      .backward();

  const DenseActorCritic network(*policy, flat);
  const Eigen::Map<const Eigen::VectorXf> parameters(flat.values().data_ptr<float>(), flat.numel());
  DenseActorCritic::Tape tape;
  network.evaluate(parameters, columns(observations), columns(actions), tape);
  EXPECT_TRUE(tape.log_prob.isApprox(row(expected.log_prob.detach()), 1e-5f));
  EXPECT_TRUE(tape.entropy.isApprox(row(expected.entropy.detach().contiguous()), 1e-5f));
  EXPECT_TRUE(tape.value.isApprox(row(expected.value.detach().contiguous()), 1e-5f));

  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(flat.numel());
  network.backward(parameters, tape, row(log_prob_weight), row(entropy_weight), row(value_weight),
                   gradient);
  const Eigen::Map<const Eigen::VectorXf> reference(flat.gradients().data_ptr<float>(),
                                                    flat.numel());
  EXPECT_LE((gradient - reference).norm(), 1e-4f * reference.norm());
}

TEST(DenseActorCritic, GaussianMatchesTheModule) {
  ActorCriticSpec spec;
  spec.observation_size = 5;
  spec.action_size = 3;
  spec.log_std_init = -0.5;
  check_against_module(spec);
  spec.shared_trunk = true;
  check_against_module(spec);
}

TEST(DenseActorCritic, CategoricalMatchesTheModule) {
  ActorCriticSpec spec;
  spec.observation_size = 4;
  spec.discrete = true;
  spec.action_size = 5;
  spec.activation = Activation::kRelu;
  spec.value_layers = {16};
  check_against_module(spec);
}

TEST(DenseActorCritic, RefusesParametersOutsideTheFlatBuffer) {
  ActorCriticSpec spec;
  spec.observation_size = 3;
  spec.action_size = 1;
  Rng init_rng(1);
  ActorCritic flattened(spec, init_rng), other(spec, init_rng);
  FlatParameters flat(flattened->parameters());
  EXPECT_NE(testing::error_message([&] { DenseActorCritic(*other, flat); }).find("flat"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::nn
