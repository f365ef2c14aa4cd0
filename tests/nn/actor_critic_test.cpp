// The hand-written actor-critic passes, KL and Fisher-vector products against LibTorch autograd
// of the same computation over the same flat parameters.
#include "tendril/nn/actor_critic.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "support/torch_networks.hpp"

namespace tendril::nn {
namespace {

using testing::columns_of;
using testing::leaf;
using testing::rows_of;
using testing::TorchActorCritic;
using testing::vector_of;

constexpr int64_t kBatch = 20;

struct Case {
  ActorCriticSpec spec;
  Eigen::VectorXf parameters;
  Eigen::MatrixXf observations, actions;
};

Case make_case(ActorCriticSpec spec, uint64_t seed = 11) {
  Case c{spec, {}, {}, {}};
  const ActorCritic network(spec);
  c.parameters.resize(network.parameter_count());
  Rng rng(seed);
  network.initialize(c.parameters, rng);
  // Larger than SB3's initial weights so that every derivative is far from trivial.
  for (Eigen::Index i = 0; i < c.parameters.size(); ++i) {
    c.parameters[i] += static_cast<float>(0.3 * rng.normal());
  }
  c.observations = Eigen::MatrixXf::Random(spec.observation_size, kBatch);
  if (spec.discrete) {
    c.actions.resize(1, kBatch);
    for (int64_t i = 0; i < kBatch; ++i) {
      c.actions(0, i) = static_cast<float>(rng.below(static_cast<uint64_t>(spec.action_size)));
    }
  } else {
    c.actions = Eigen::MatrixXf::Random(spec.action_size, kBatch) * 2.0f;
  }
  return c;
}

ActorCriticSpec gaussian(bool shared = false) {
  ActorCriticSpec spec;
  spec.observation_size = 5;
  spec.action_size = 3;
  spec.log_std_init = -0.5;
  spec.shared_trunk = shared;
  return spec;
}

ActorCriticSpec categorical() {
  ActorCriticSpec spec;
  spec.observation_size = 4;
  spec.discrete = true;
  spec.action_size = 5;
  spec.activation = Activation::kRelu;
  spec.value_layers = {16};
  return spec;
}

// evaluate() equals the LibTorch computation, and backward() of per-sample weights w equals
// autograd of Σ_t (w_logπ log π_t + w_H H_t + w_V V_t).
void check_evaluate_and_backward(const ActorCriticSpec& spec) {
  const Case c = make_case(spec);
  const ActorCritic network(spec);
  torch::manual_seed(3);
  const torch::Tensor log_prob_weight = torch::randn({kBatch});
  const torch::Tensor entropy_weight = torch::randn({kBatch});
  const torch::Tensor value_weight = torch::randn({kBatch});

  const torch::Tensor theta = leaf(c.parameters);
  const TorchActorCritic reference(spec, theta, rows_of(c.observations));
  const torch::Tensor log_prob = reference.log_prob(rows_of(c.actions), spec.discrete);
  const torch::Tensor entropy = reference.entropy(spec.discrete);
  ((log_prob * log_prob_weight).sum() + (entropy * entropy_weight).sum() +
   (reference.value * value_weight).sum())
      .backward();

  ActorCritic::Tape tape;
  network.evaluate(c.parameters, c.observations, c.actions, tape);
  EXPECT_TRUE(tape.log_prob.transpose().isApprox(vector_of(log_prob), 1e-5f));
  EXPECT_TRUE(tape.entropy.transpose().isApprox(vector_of(entropy), 1e-5f));
  EXPECT_TRUE(tape.value.transpose().isApprox(vector_of(reference.value), 1e-5f));

  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(network.parameter_count());
  network.backward(c.parameters, tape, vector_of(log_prob_weight).transpose(),
                   vector_of(entropy_weight).transpose(), vector_of(value_weight).transpose(),
                   gradient);
  const Eigen::VectorXf expected = vector_of(theta.grad());
  EXPECT_LE((gradient - expected).norm(), 1e-4f * expected.norm());
}

TEST(ActorCritic, GaussianPassesMatchAutograd) {
  check_evaluate_and_backward(gaussian());
  check_evaluate_and_backward(gaussian(/*shared=*/true));
  ActorCriticSpec no_trunk = gaussian();
  no_trunk.policy_layers = {};
  no_trunk.value_layers = {};
  check_evaluate_and_backward(no_trunk);
}

TEST(ActorCritic, CategoricalPassesMatchAutograd) {
  check_evaluate_and_backward(categorical());
  ActorCriticSpec shared = categorical();
  shared.shared_trunk = true;
  check_evaluate_and_backward(shared);
}

// The parts used alone (TRPO): the policy's evaluation and gradient, and the value's.
TEST(ActorCritic, PolicyAndValuePartsEqualTheWholeAndStayInTheirBlocks) {
  const ActorCriticSpec spec = gaussian();
  const Case c = make_case(spec);
  const ActorCritic network(spec);
  const Eigen::RowVectorXf w = Eigen::RowVectorXf::Random(kBatch);
  const Eigen::RowVectorXf zero = Eigen::RowVectorXf::Zero(kBatch);
  ActorCritic::Tape whole, part;
  network.evaluate(c.parameters, c.observations, c.actions, whole);
  Eigen::VectorXf expected = Eigen::VectorXf::Zero(network.parameter_count());
  network.backward(c.parameters, whole, w, zero, zero, expected);
  network.evaluate_policy(c.parameters, c.observations, c.actions, part);
  Eigen::VectorXf policy_gradient = Eigen::VectorXf::Zero(network.parameter_count());
  network.backward_policy(c.parameters, part, w, zero, policy_gradient);
  EXPECT_TRUE(policy_gradient.isApprox(expected, 1e-6f));
  const int64_t policy_count = network.policy_parameter_count();
  EXPECT_EQ(policy_gradient.tail(network.parameter_count() - policy_count).norm(), 0.0f);

  Eigen::VectorXf values;
  network.value(c.parameters, c.observations, values, part);
  EXPECT_TRUE(values.isApprox(whole.value.transpose(), 1e-6f));
  Eigen::VectorXf value_gradient = Eigen::VectorXf::Zero(network.parameter_count());
  network.backward_value(c.parameters, part, w, value_gradient);
  Eigen::VectorXf expected_value = Eigen::VectorXf::Zero(network.parameter_count());
  network.backward(c.parameters, whole, zero, zero, w, expected_value);
  EXPECT_TRUE(value_gradient.isApprox(expected_value, 1e-6f));
  EXPECT_EQ(value_gradient.head(policy_count).norm(), 0.0f);
  EXPECT_GT(value_gradient.norm(), 0.0f);
}

// F v against autograd's Hessian-vector product of the mean KL(π_old ‖ π_θ) at θ = θ_old, and
// the KL itself at a moved θ.
void check_fisher_and_kl(const ActorCriticSpec& spec) {
  const Case c = make_case(spec);
  const ActorCritic network(spec);
  const int64_t policy_count = network.policy_parameter_count();
  Rng rng(5);
  Eigen::VectorXf tangent(policy_count);
  for (Eigen::Index i = 0; i < tangent.size(); ++i) tangent[i] = static_cast<float>(rng.normal());

  const torch::Tensor observations = rows_of(c.observations);
  const torch::Tensor theta = leaf(c.parameters);
  const TorchActorCritic old_reference(spec, theta.detach(), observations);
  const TorchActorCritic reference(spec, theta, observations);
  const torch::Tensor kl = reference.mean_kl(old_reference, spec.discrete);
  const torch::Tensor kl_gradient = torch::autograd::grad({kl}, {theta}, {}, true, true)[0];
  const torch::Tensor v = torch::cat({torch::from_blob(tangent.data(), {policy_count}).clone(),
                                      torch::zeros({network.parameter_count() - policy_count})});
  const torch::Tensor hessian_vector = torch::autograd::grad({(kl_gradient * v).sum()}, {theta})[0];

  ActorCritic::Tape tape;
  network.evaluate_policy(c.parameters, c.observations, c.actions, tape);
  Eigen::VectorXf product(policy_count);
  network.fisher_vector_product(c.parameters, tape, tangent, product);
  const Eigen::VectorXf expected = vector_of(hessian_vector).head(policy_count);
  EXPECT_LE((product - expected).norm(), 1e-4f * expected.norm()) << expected.norm();
  EXPECT_GT(expected.norm(), 1e-3f);

  // The closed-form KL against a moved policy.
  Eigen::VectorXf moved = c.parameters;
  moved.head(policy_count) += 0.05f * tangent;
  ActorCritic::Tape moved_tape;
  network.evaluate_policy(moved, c.observations, c.actions, moved_tape);
  const double ours = network.mean_kl(network.distribution(c.parameters, tape),
                                      network.distribution(moved, moved_tape));
  const TorchActorCritic moved_reference(spec, leaf(moved).detach(), observations);
  const double theirs = moved_reference.mean_kl(old_reference, spec.discrete).item<double>();
  EXPECT_NEAR(ours, theirs, 1e-5 * theirs + 1e-9);
  EXPECT_GT(theirs, 1e-5);
}

TEST(ActorCritic, GaussianFisherVectorProductIsTheKlHessian) {
  check_fisher_and_kl(gaussian());
  check_fisher_and_kl(gaussian(/*shared=*/true));
}

TEST(ActorCritic, CategoricalFisherVectorProductIsTheKlHessian) {
  check_fisher_and_kl(categorical());
}

TEST(ActorCritic, ActingTakesTheModeOrSamplesWithTheRightLogProbabilities) {
  const ActorCriticSpec spec = gaussian();
  const Case c = make_case(spec);
  const ActorCritic network(spec);
  ActorCritic::Tape tape;
  Rng rng(2);
  Eigen::MatrixXf actions;
  Eigen::VectorXf log_probs;
  network.act(c.parameters, c.observations, /*deterministic=*/true, rng, actions, log_probs, tape);
  ActorCritic::Tape reference;
  network.evaluate_policy(c.parameters, c.observations, actions, reference);
  EXPECT_TRUE(actions.isApprox(reference.policy_head.tape.output()));
  EXPECT_TRUE(log_probs.isApprox(reference.log_prob.transpose(), 1e-5f));

  // Samples of one observation: mean μ and standard deviation σ = exp(log σ).
  const Eigen::MatrixXf one = c.observations.col(0).replicate(1, 20000);
  network.act(c.parameters, one, /*deterministic=*/false, rng, actions, log_probs, tape);
  network.evaluate_policy(c.parameters, one, actions, reference);
  EXPECT_TRUE(log_probs.isApprox(reference.log_prob.transpose(), 1e-4f));
  const Eigen::VectorXf mean = actions.rowwise().mean();
  const Eigen::VectorXf std_dev =
      ((actions.colwise() - mean).array().square().rowwise().mean()).sqrt();
  const auto log_std = c.parameters.segment(network.log_std_offset(), spec.action_size);
  for (int j = 0; j < spec.action_size; ++j) {
    EXPECT_NEAR(mean[j], reference.policy_head.tape.output()(j, 0), 0.03f);
    EXPECT_NEAR(std_dev[j], std::exp(log_std[j]), 0.03f * std::exp(log_std[j]));
  }
}

TEST(ActorCritic, CategoricalSamplesFollowTheSoftmax) {
  const ActorCriticSpec spec = categorical();
  const Case c = make_case(spec);
  const ActorCritic network(spec);
  const Eigen::MatrixXf one = c.observations.col(0).replicate(1, 50000);
  ActorCritic::Tape tape;
  Rng rng(9);
  Eigen::MatrixXf actions;
  Eigen::VectorXf log_probs;
  network.act(c.parameters, one, /*deterministic=*/false, rng, actions, log_probs, tape);
  const Eigen::VectorXf logits = tape.policy_head.tape.output().col(0);
  const Eigen::VectorXf p =
      (logits.array() - logits.maxCoeff()).exp() / (logits.array() - logits.maxCoeff()).exp().sum();
  for (int k = 0; k < spec.action_size; ++k) {
    const double frequency = (actions.array() == static_cast<float>(k)).cast<double>().mean();
    EXPECT_NEAR(frequency, p[k], 0.01) << "choice " << k;
  }
  network.act(c.parameters, one.leftCols(1), /*deterministic=*/true, rng, actions, log_probs, tape);
  Eigen::Index best;
  logits.maxCoeff(&best);
  EXPECT_EQ(actions(0, 0), static_cast<float>(best));
}

TEST(ActorCritic, InitialisationIsSb3sOrthogonalSchemeAndSeeded) {
  ActorCriticSpec spec = gaussian();
  spec.policy_layers = {64, 64};
  const ActorCritic network(spec);
  Eigen::VectorXf a(network.parameter_count()), b(network.parameter_count());
  Rng rng_a(4), rng_b(4);
  network.initialize(a, rng_a);
  network.initialize(b, rng_b);
  EXPECT_EQ(a, b);
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  // First policy layer (64 × 5): orthonormal columns scaled by √2; its bias zero.
  const Eigen::Map<const RowMajor> first(a.data(), 64, 5);
  EXPECT_TRUE((first.transpose() * first).isApprox(2.0f * Eigen::MatrixXf::Identity(5, 5), 1e-5f));
  EXPECT_EQ(a.segment(64 * 5, 64).norm(), 0.0f);
  // The policy head (3 × 64) follows the trunk: orthonormal rows scaled by 0.01.
  const int64_t head = 64 * 6 + 64 * 65;
  const Eigen::Map<const RowMajor> head_weight(a.data() + head, 3, 64);
  EXPECT_TRUE((head_weight * head_weight.transpose())
                  .isApprox(1e-4f * Eigen::MatrixXf::Identity(3, 3), 1e-4f));
  EXPECT_EQ(a.segment(network.log_std_offset(), 3), Eigen::VectorXf::Constant(3, -0.5f));
  EXPECT_EQ(network.log_std_offset(), head + 3 * 65);
  EXPECT_EQ(network.policy_parameter_count(), network.log_std_offset() + 3);
}

TEST(ActorCritic, RejectsEmptySpaces) {
  ActorCriticSpec spec = gaussian();
  spec.action_size = 0;
  EXPECT_EQ(testing::error_message([&] { ActorCritic network(spec); }),
            "nn::ActorCritic: action size must be positive");
}

}  // namespace
}  // namespace tendril::nn
