// One PPO iteration against an independent LibTorch-autograd implementation of
// Stable-Baselines3's PPO.train (stable_baselines3/ppo/ppo.py; Schulman et al. 2017, eq. 9) on
// the rollout the algorithm just collected: epochs of shuffled minibatches, the advantages
// standardised per minibatch, the clipped surrogate with value clipping and entropy bonus, the
// global gradient-norm clip, Adam (ε 1e-5), the early stop once the approximate KL of a
// minibatch exceeds 1.5 × target_kl, and the learning-rate and clip-range schedules at the
// progress of the iteration. Compares the logged losses and every parameter afterwards. The
// minibatch order is replayed from a copy of the algorithm's shuffling stream. (The loss
// gradient of one minibatch alone is ppo_gradient_test's.)
#include <gtest/gtest.h>
#include <torch/torch.h>

#include "support/reference_networks.hpp"
#include "support/rollout_tensors.hpp"
#include "support/torch_networks.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

using namespace tendril::testing;

// Keeps what the update starts from: the parameters, the rollout and the shuffling stream.
class PpoUnderTest : public Ppo {
 public:
  using Ppo::Ppo;

  struct Start {
    Eigen::VectorXf parameters;
    RolloutBuffer buffer{1, 1, 1, 1};
    Rng shuffle;
    double progress_remaining = 0.0;
  };
  Start start;
  TrainStats stats;

 protected:
  TrainStats train(double progress_remaining) override {
    start.parameters = parameters();
    start.buffer = buffer();
    start.shuffle = shuffle_rng();
    start.progress_remaining = progress_remaining;
    stats = Ppo::train(progress_remaining);
    return stats;
  }
};

struct ReferenceResult {
  Eigen::VectorXf parameters;
  double policy_loss = 0.0, value_loss = 0.0, entropy_loss = 0.0, clip_fraction = 0.0;
  double approx_kl = 0.0, last_loss = 0.0;
  int64_t minibatches = 0;  // evaluated, the one that stopped the epochs included
  int64_t steps = 0;        // gradient steps taken
  int64_t clipped_norms = 0;
  bool stopped_early = false;
};

// SB3's PPO.train on the flat parameters of `spec`'s actor-critic.
ReferenceResult reference_train(const nn::ActorCriticSpec& spec, const PpoUnderTest::Start& start,
                                const PpoConfig& config) {
  const double progress = start.progress_remaining;
  const double learning_rate = config.learning_rate.at(progress);
  const double clip_range = config.clip_range.at(progress);
  const torch::Tensor theta = leaf(start.parameters);
  torch::optim::Adam optimizer({theta},
                               torch::optim::AdamOptions(learning_rate).eps(config.adam_epsilon));
  const RolloutBuffer& buffer = start.buffer;
  const torch::Tensor observations = sample_rows(buffer.observations());
  const torch::Tensor actions = sample_rows(buffer.actions());
  const torch::Tensor old_log_probs = sample_values(buffer.log_probs());
  const torch::Tensor old_values = sample_values(buffer.values());
  const torch::Tensor all_advantages = sample_values(buffer.advantages());
  const torch::Tensor returns = sample_values(buffer.returns());
  Rng shuffle = start.shuffle;
  ReferenceResult result;
  for (int64_t epoch = 0; epoch < config.n_epochs && !result.stopped_early; ++epoch) {
    for (const torch::Tensor& index :
         shuffled_minibatches(buffer.size(), config.batch_size, shuffle)) {
      const TorchActorCritic evaluation(spec, theta, observations.index_select(0, index));
      const torch::Tensor log_prob =
          evaluation.log_prob(actions.index_select(0, index), spec.discrete);
      torch::Tensor advantages = all_advantages.index_select(0, index);
      if (config.common.normalize_advantage && advantages.numel() > 1) {
        advantages = (advantages - advantages.mean()) / (advantages.std() + 1e-8);
      }
      const torch::Tensor batch_old_log_probs = old_log_probs.index_select(0, index);
      const torch::Tensor ratio = torch::exp(log_prob - batch_old_log_probs);
      const torch::Tensor policy_loss =
          -torch::min(advantages * ratio,
                      advantages * torch::clamp(ratio, 1 - clip_range, 1 + clip_range))
               .mean();
      torch::Tensor predicted = evaluation.value;
      if (config.clip_range_vf) {
        const torch::Tensor batch_old_values = old_values.index_select(0, index);
        predicted = batch_old_values + torch::clamp(evaluation.value - batch_old_values,
                                                    -*config.clip_range_vf, *config.clip_range_vf);
      }
      const torch::Tensor value_loss = torch::mse_loss(returns.index_select(0, index), predicted);
      const torch::Tensor entropy_loss = -evaluation.entropy(spec.discrete).mean();
      const torch::Tensor loss =
          policy_loss + config.ent_coef * entropy_loss + config.vf_coef * value_loss;
      result.policy_loss += policy_loss.item<double>();
      result.value_loss += value_loss.item<double>();
      result.entropy_loss += entropy_loss.item<double>();
      result.clip_fraction +=
          ((ratio - 1).abs() > clip_range).to(torch::kFloat).mean().item<double>();
      result.last_loss = loss.item<double>();
      ++result.minibatches;
      const torch::Tensor log_ratio = (log_prob - batch_old_log_probs).detach();
      const double approx_kl = ((log_ratio.exp() - 1) - log_ratio).mean().item<double>();
      result.approx_kl += approx_kl;
      if (config.target_kl && approx_kl > 1.5 * *config.target_kl) {
        result.stopped_early = true;
        break;
      }
      optimizer.zero_grad();
      loss.backward();
      if (config.max_grad_norm) {
        const double norm = torch::nn::utils::clip_grad_norm_({theta}, *config.max_grad_norm);
        if (norm > *config.max_grad_norm) ++result.clipped_norms;
      }
      optimizer.step();
      ++result.steps;
    }
  }
  result.parameters = vector_of(theta);
  return result;
}

struct Case {
  const char* name;
  const char* env;
  const char* algo;
  bool expect_early_stop;
};

class PpoUpdate : public ::testing::TestWithParam<Case> {};

TEST_P(PpoUpdate, OneIterationMatchesStableBaselines3UpdateWrittenWithAutograd) {
  VecEnvOptions options;
  options.id = GetParam().env;
  options.n_envs = 2;
  auto env = make_vec_env(options);
  const PpoConfig config = PpoConfig::from_config(Config::parse(GetParam().algo));
  PpoUnderTest agent(*env, config, 5);
  const int64_t rollout = config.common.n_steps * 2;
  // Two rollouts' budget, stopped after the first: its update runs at progress 1/2, where the
  // linear schedules have halved.
  agent.learn(2 * rollout, [](const Progress&) { return false; });
  ASSERT_EQ(agent.num_timesteps(), rollout);
  ASSERT_DOUBLE_EQ(agent.start.progress_remaining, 0.5);

  const nn::ActorCriticSpec& spec = agent.actor_critic().network().spec();
  const ReferenceResult expected = reference_train(spec, agent.start, config);
  const TrainStats& stats = agent.stats;

  // The scenario exercises what it claims: the norm clip binds on some steps, and the early
  // stop fires (or not) after some steps were taken.
  EXPECT_GT(expected.clipped_norms, 0);
  EXPECT_EQ(expected.stopped_early, GetParam().expect_early_stop);
  EXPECT_GT(expected.steps, 1);

  const auto n = static_cast<double>(expected.minibatches);
  EXPECT_EQ(stat(stats, "train/n_updates"), n);
  EXPECT_NEAR(stat(stats, "train/policy_gradient_loss"), expected.policy_loss / n,
              1e-5 * std::abs(expected.policy_loss / n) + 1e-7);
  EXPECT_NEAR(stat(stats, "train/value_loss"), expected.value_loss / n,
              1e-5 * std::abs(expected.value_loss / n));
  EXPECT_NEAR(stat(stats, "train/entropy_loss"), expected.entropy_loss / n,
              1e-5 * std::abs(expected.entropy_loss / n));
  EXPECT_NEAR(stat(stats, "train/approx_kl"), expected.approx_kl / n,
              1e-3 * expected.approx_kl / n + 1e-8);
  EXPECT_NEAR(stat(stats, "train/clip_fraction"), expected.clip_fraction / n, 1e-6);
  EXPECT_NEAR(stat(stats, "train/loss"), expected.last_loss, 1e-5 * std::abs(expected.last_loss));
  EXPECT_NEAR(stat(stats, "train/learning_rate"), config.learning_rate.at(0.5), 1e-12);
  EXPECT_NEAR(stat(stats, "train/clip_range"), config.clip_range.at(0.5), 1e-12);

  // Every parameter, to float rounding of the Adam steps (each moves a parameter by about the
  // learning rate).
  const double step_size = config.learning_rate.at(0.5);
  const Eigen::VectorXf& after = agent.actor_critic().parameters();
  EXPECT_GT(max_difference(after, agent.start.parameters), 0.5 * step_size);
  EXPECT_LT(max_difference(after, expected.parameters), 2e-3 * step_size);
}

INSTANTIATE_TEST_SUITE_P(
    Settings, PpoUpdate,
    ::testing::Values(
        Case{"GaussianEarlyStopAndSchedules", "Pendulum-v1",
             "n_steps: 64\nbatch_size: 32\nn_epochs: 6\nlearning_rate: 3e-3\n"
             "learning_rate_schedule: linear\nclip_range: 0.3\nclip_range_schedule: linear\n"
             "ent_coef: 0.01\nmax_grad_norm: 0.5\ntarget_kl: 0.0007\n"
             "policy: {net_arch: [16, 16]}\n",
             true},
        Case{"CategoricalValueClipping", "CartPole-v1",
             "n_steps: 64\nbatch_size: 24\nn_epochs: 3\nlearning_rate: 2e-3\n"
             "learning_rate_schedule: linear\nclip_range: 0.2\nclip_range_vf: 0.1\n"
             "ent_coef: 0.02\nvf_coef: 0.7\nmax_grad_norm: 0.3\npolicy: {net_arch: [16, 16]}\n",
             false}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace tendril::rl
