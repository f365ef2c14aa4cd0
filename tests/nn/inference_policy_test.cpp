#include "tendril/nn/inference_policy.hpp"

#include <gtest/gtest.h>

#include "tendril/nn/actor_critic.hpp"
#include "tendril/nn/inference_sync.hpp"

namespace tendril::nn {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A [batch, size] row-major matrix as a tensor (copied) and as Eigen columns (in place).
torch::Tensor to_tensor(const RowMatrix& rows) {
  return torch::from_blob(const_cast<float*>(rows.data()), {rows.rows(), rows.cols()},
                          torch::kFloat)
      .clone();
}
Eigen::Map<const Eigen::MatrixXf> columns(const RowMatrix& rows) {
  return {rows.data(), rows.cols(), rows.rows()};
}

RowMatrix random_observations(int batch, int size, uint64_t seed) {
  Rng rng(seed);
  RowMatrix rows(batch, size);
  for (int i = 0; i < batch; ++i) {
    for (int j = 0; j < size; ++j) rows(i, j) = static_cast<float>(rng.normal());
  }
  return rows;
}

TEST(InferencePolicy, GaussianMatchesTheTorchModule) {
  for (bool shared : {false, true}) {
    Rng init(3);
    ActorCriticSpec spec =
        ActorCriticSpec{}.with_spaces(Space::box(3, -1, 1), Space::box(2, -1, 1));
    spec.shared_trunk = shared;
    spec.log_std_init = -0.7;
    ActorCritic model(spec, init);
    // Move away from the near-zero initial head so the comparison is meaningful.
    {
      torch::NoGradGuard no_grad;
      for (auto& p : model->parameters()) p.add_(torch::randn(p.sizes()) * 0.3);
    }
    InferencePolicy policy = make_inference_policy(*model);
    const RowMatrix observations = random_observations(16, 3, 1);
    const torch::Tensor obs = to_tensor(observations);

    Eigen::MatrixXf actions;
    Eigen::VectorXf log_probs, values;
    Rng sampler(4);
    policy.act(columns(observations), /*deterministic=*/false, sampler, actions, log_probs);
    policy.value(columns(observations), values);
    const torch::Tensor action_tensor =
        torch::from_blob(actions.data(), {16, 2}, torch::TensorOptions().dtype(torch::kFloat))
            .clone();  // column-major 2 × 16 is row-major 16 × 2
    const auto evaluation = model->evaluate(obs, action_tensor);
    for (int i = 0; i < 16; ++i) {
      EXPECT_NEAR(log_probs[i], evaluation.log_prob[i].item<float>(), 1e-4);
      EXPECT_NEAR(values[i], evaluation.value[i].item<float>(), 1e-4);
    }

    policy.act(columns(observations), /*deterministic=*/true, sampler, actions, log_probs);
    const torch::Tensor mean = model->distribution(obs).mean;
    for (int i = 0; i < 16; ++i) {
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(actions(k, i), mean[i][k].item<float>(), 1e-5);
    }
  }
}

TEST(InferencePolicy, CategoricalSamplesFollowTheSoftmax) {
  Rng init(8);
  ActorCriticSpec spec = ActorCriticSpec{}.with_spaces(Space::box(2, -1, 1), Space::discrete(3));
  ActorCritic model(spec, init);
  {
    torch::NoGradGuard no_grad;
    model->policy_head()->bias.copy_(torch::tensor({1.0f, 0.0f, -1.0f}));
  }
  InferencePolicy policy = make_inference_policy(*model);
  const RowMatrix observations = RowMatrix::Zero(20000, 2);
  Eigen::MatrixXf actions;
  Eigen::VectorXf log_probs;
  Rng sampler(12);
  policy.act(columns(observations), false, sampler, actions, log_probs);
  const torch::Tensor probabilities =
      torch::softmax(model->distribution(torch::zeros({1, 2})).logits, -1)[0];
  for (int k = 0; k < 3; ++k) {
    const double frequency = (actions.array() == static_cast<float>(k)).cast<double>().mean();
    EXPECT_NEAR(frequency, probabilities[k].item<double>(), 0.01);
  }
  // Log-probabilities are those of the chosen actions.
  for (int i = 0; i < 5; ++i) {
    const auto k = static_cast<int64_t>(actions(0, i));
    EXPECT_NEAR(std::exp(log_probs[i]), probabilities[k].item<float>(), 1e-5);
  }
  policy.act(columns(observations.topRows(1)), true, sampler, actions, log_probs);
  EXPECT_EQ(actions(0, 0), 0.0f);
}

TEST(InferencePolicy, SyncFollowsParameterChanges) {
  Rng init(1);
  ActorCriticSpec spec = ActorCriticSpec{}.with_spaces(Space::box(2, -1, 1), Space::box(1, -1, 1));
  ActorCritic model(spec, init);
  InferencePolicy policy = make_inference_policy(*model);
  const RowMatrix observations = random_observations(4, 2, 2);
  Eigen::VectorXf before, after;
  policy.value(columns(observations), before);
  {
    torch::NoGradGuard no_grad;
    model->value_head()->bias.add_(1.5);
  }
  sync_inference_policy(*model, policy);
  policy.value(columns(observations), after);
  EXPECT_TRUE(((after - before).array() - 1.5f).abs().maxCoeff() < 1e-5f);
}

}  // namespace
}  // namespace tendril::nn
