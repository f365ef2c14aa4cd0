// One TRPO update against an independent LibTorch-autograd implementation of the step of
// Schulman et al. 2015 (section 6, appendix C) as SB3-contrib's TRPO.train takes it, on the
// rollout the algorithm just collected: the surrogate's gradient g, the Fisher-vector product
// (Hessian of the mean KL at θold by double backward, plus damping), the conjugate-gradient
// direction s ≈ F⁻¹g, the step β = sqrt(2δ / sᵀFs), the backtracking line search, and the value
// function's Adam fit over shuffled minibatches. Besides the parameters it checks the step's
// defining properties directly: the accepted step keeps the mean KL(π_old ‖ π_new) — σ's change
// included — within δ and improves the surrogate; a rejected search leaves the policy as it was.
#include <gtest/gtest.h>
#include <torch/torch.h>

#include <functional>

#include "support/reference_networks.hpp"
#include "support/rollout_tensors.hpp"
#include "support/torch_networks.hpp"
#include "tendril/rl/trpo/trpo.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace tendril::rl {
namespace {

using namespace tendril::testing;

class TrpoUnderTest : public Trpo {
 public:
  using Trpo::Trpo;

  struct Start {
    Eigen::VectorXf parameters;
    RolloutBuffer buffer{1, 1, 1, 1};
    Rng shuffle;
  };
  Start start;
  TrainStats stats;

 protected:
  TrainStats train(double progress_remaining) override {
    start.parameters = parameters();
    start.buffer = buffer();
    start.shuffle = shuffle_rng();
    stats = Trpo::train(progress_remaining);
    return stats;
  }
};

// SB3-contrib's conjugate_gradient_solver.
torch::Tensor solve(const std::function<torch::Tensor(const torch::Tensor&)>& product,
                    const torch::Tensor& b, int64_t max_steps) {
  torch::Tensor x = torch::zeros_like(b);
  torch::Tensor residual = b.clone();
  torch::Tensor squared = residual.dot(residual);
  if (squared.item<double>() < 1e-10) return x;
  torch::Tensor p = residual.clone();
  for (int64_t i = 0; i < max_steps; ++i) {
    const torch::Tensor ap = product(p);
    const torch::Tensor alpha = squared / p.dot(ap);
    x = x + alpha * p;
    if (i == max_steps - 1) break;
    residual = residual - alpha * ap;
    const torch::Tensor next = residual.dot(residual);
    if (next.item<double>() < 1e-10) break;
    p = residual + (next / squared) * p;
    squared = next;
  }
  return x;
}

// The rollout as tensors, with the advantages standardised over the whole rollout.
struct Rollout {
  torch::Tensor observations, actions, old_log_probs, advantages, returns;

  Rollout(const RolloutBuffer& buffer, bool normalize) {
    observations = sample_rows(buffer.observations());
    actions = sample_rows(buffer.actions());
    old_log_probs = sample_values(buffer.log_probs());
    returns = sample_values(buffer.returns());
    advantages = sample_values(buffer.advantages());
    if (normalize) advantages = (advantages - advantages.mean()) / (advantages.std() + 1e-8);
  }
  // Ê[π_θ(a|s) / π_θold(a|s) Â]
  torch::Tensor surrogate(const nn::ActorCriticSpec& spec, const torch::Tensor& theta) const {
    const TorchActorCritic policy(spec, theta, observations);
    return (torch::exp(policy.log_prob(actions, spec.discrete) - old_log_probs) * advantages)
        .mean();
  }
};

struct Expected {
  Eigen::VectorXf parameters;
  bool accepted = false;
  int64_t line_search_steps = 0;
  double value_loss = 0.0;
};

Expected reference_train(const nn::ActorCriticSpec& spec, int64_t policy_count,
                         const TrpoUnderTest::Start& start, const TrpoConfig& config) {
  const Rollout rollout(start.buffer, config.common.normalize_advantage);
  const int64_t value_count = start.parameters.size() - policy_count;
  const torch::Tensor all = leaf(start.parameters).detach();
  const torch::Tensor policy = all.narrow(0, 0, policy_count).clone().requires_grad_(true);
  const torch::Tensor value = all.narrow(0, policy_count, value_count).clone().requires_grad_(true);
  const auto theta = [&] { return torch::cat({policy, value}); };
  // θold's distribution, in tensors of its own.
  const TorchActorCritic old(spec, all.clone(), rollout.observations);

  const torch::Tensor objective = rollout.surrogate(spec, theta());
  const torch::Tensor g = torch::autograd::grad({objective}, {policy})[0];
  const torch::Tensor kl =
      TorchActorCritic(spec, theta(), rollout.observations).mean_kl(old, spec.discrete);
  const torch::Tensor kl_gradient = torch::autograd::grad({kl}, {policy}, {}, true, true)[0];
  const auto fisher = [&](const torch::Tensor& v) {
    return torch::autograd::grad({(kl_gradient * v).sum()}, {policy}, {}, true)[0] +
           config.cg_damping * v;
  };
  const torch::Tensor direction = solve(fisher, g, config.cg_max_steps);
  const double max_step =
      std::sqrt(2 * config.target_kl / direction.dot(fisher(direction)).item<double>());

  Expected result;
  const double old_surrogate = objective.item<double>();
  const torch::Tensor old_policy = policy.detach().clone();
  {
    torch::NoGradGuard no_grad;
    double coefficient = 1.0;
    for (; result.line_search_steps < config.line_search_max_iter; ++result.line_search_steps) {
      policy.copy_(old_policy + coefficient * max_step * direction);
      const double new_surrogate = rollout.surrogate(spec, theta()).item<double>();
      const double new_kl = TorchActorCritic(spec, theta(), rollout.observations)
                                .mean_kl(old, spec.discrete)
                                .item<double>();
      if (new_kl < config.target_kl && new_surrogate > old_surrogate) {
        result.accepted = true;
        break;
      }
      coefficient *= config.line_search_shrinking_factor;
    }
    if (!result.accepted) policy.copy_(old_policy);
  }

  // The value function: n_critic_updates epochs of Adam over shuffled minibatches.
  torch::optim::Adam optimizer(
      {value}, torch::optim::AdamOptions(config.learning_rate).eps(config.adam_epsilon));
  Rng shuffle = start.shuffle;
  int64_t steps = 0;
  for (int64_t epoch = 0; epoch < config.n_critic_updates; ++epoch) {
    for (const torch::Tensor& index :
         shuffled_minibatches(start.buffer.size(), config.batch_size, shuffle)) {
      const TorchActorCritic evaluation(spec, theta(), rollout.observations.index_select(0, index));
      const torch::Tensor loss =
          (rollout.returns.index_select(0, index) - evaluation.value).pow(2).mean();
      optimizer.zero_grad();
      loss.backward();
      optimizer.step();
      result.value_loss += loss.item<double>();
      ++steps;
    }
  }
  result.value_loss /= static_cast<double>(steps);
  result.parameters = vector_of(theta());
  return result;
}

// How the line search ends in a case.
enum class Search { kFullStep, kBacktracks, kRejects };

struct Case {
  const char* name;
  const char* env;
  const char* algo;
  Search search;
};

class TrpoUpdate : public ::testing::TestWithParam<Case> {};

TEST_P(TrpoUpdate, OneStepMatchesTheReferenceAndKeepsTheTrustRegion) {
  VecEnvOptions options;
  options.id = GetParam().env;
  options.n_envs = 2;
  auto env = make_vec_env(options);
  const TrpoConfig config = TrpoConfig::from_config(Config::parse(GetParam().algo));
  TrpoUnderTest agent(*env, config, 6);
  agent.learn(config.common.n_steps * 2);
  const nn::ActorCritic& network = agent.actor_critic().network();
  const nn::ActorCriticSpec& spec = network.spec();
  const int64_t policy_count = network.policy_parameter_count();

  const Expected expected = reference_train(spec, policy_count, agent.start, config);
  const TrainStats& stats = agent.stats;
  EXPECT_EQ(stat(stats, "train/is_line_search_success"), expected.accepted ? 1.0 : 0.0);
  EXPECT_EQ(stat(stats, "train/line_search_steps"),
            static_cast<double>(expected.line_search_steps));
  EXPECT_NEAR(stat(stats, "train/value_loss"), expected.value_loss, 1e-4 * expected.value_loss);
  const Eigen::VectorXf& before = agent.start.parameters;
  const Eigen::VectorXf& after = agent.actor_critic().parameters();
  // The policy to float rounding of the conjugate-gradient solve, which the ill-conditioned
  // Fisher matrix of the small-damping cases amplifies in proportion to the step; the value
  // function to float rounding of its Adam steps.
  const int64_t value_count = after.size() - policy_count;
  const double policy_step = max_difference(after.head(policy_count), before.head(policy_count));
  EXPECT_LT(max_difference(after.head(policy_count), expected.parameters.head(policy_count)),
            1e-5 + 1e-3 * policy_step);
  EXPECT_LT(max_difference(after.tail(value_count), expected.parameters.tail(value_count)), 1e-5);
  EXPECT_GT(max_difference(after, before), 1e-4);

  // The scenario is the one the case is about.
  switch (GetParam().search) {
    case Search::kFullStep:
      EXPECT_TRUE(expected.accepted && expected.line_search_steps == 0);
      break;
    case Search::kBacktracks:
      EXPECT_TRUE(expected.accepted && expected.line_search_steps > 0);
      break;
    case Search::kRejects:
      EXPECT_FALSE(expected.accepted);
      break;
  }

  // The properties of the step, from the library's new parameters directly.
  if (!expected.accepted) {
    // A failed search keeps θold: the policy is unchanged, only the value function moved.
    EXPECT_EQ(max_difference(after.head(policy_count), before.head(policy_count)), 0.0);
    EXPECT_GT(max_difference(after.tail(value_count), before.tail(value_count)), 1e-4);
    return;
  }
  const Rollout rollout(agent.start.buffer, config.common.normalize_advantage);
  torch::NoGradGuard no_grad;
  const TorchActorCritic old(spec, leaf(before), rollout.observations);
  const TorchActorCritic updated(spec, leaf(after), rollout.observations);
  const double kl = updated.mean_kl(old, spec.discrete).item<double>();
  EXPECT_GT(kl, 0.0);
  EXPECT_LE(kl, config.target_kl);
  EXPECT_NEAR(stat(stats, "train/kl_divergence_loss"), kl, 1e-4 * config.target_kl);
  const double old_surrogate = rollout.surrogate(spec, leaf(before)).item<double>();
  EXPECT_NEAR(old_surrogate, 0.0, 1e-5);  // the ratio is 1 at θold and Â has mean 0
  const double new_surrogate = rollout.surrogate(spec, leaf(after)).item<double>();
  EXPECT_GT(new_surrogate, old_surrogate);
  EXPECT_NEAR(stat(stats, "train/policy_objective"), new_surrogate, 1e-5);
  if (!spec.discrete) {
    // The step moves log σ, and by enough that a KL whose "old" σ followed the new one (an old
    // policy viewing the parameters instead of holding a copy) would be told apart above.
    const auto log_std = [&](const Eigen::VectorXf& p) {
      return Eigen::VectorXf(p.segment(network.log_std_offset(), spec.action_size));
    };
    EXPECT_GT(max_difference(log_std(after), log_std(before)), 1e-4);
    TorchActorCritic aliased = old;
    aliased.log_std = updated.log_std;
    const double aliased_kl = updated.mean_kl(aliased, spec.discrete).item<double>();
    EXPECT_GT(std::abs(aliased_kl - kl), 1e-3 * config.target_kl);
  }
}

// With the damping small (10⁻⁴), the quadratic model of the KL underestimates it at the full step,
// so the search must shrink the step (Pendulum), or finds no improving step at all (CartPole).
INSTANTIATE_TEST_SUITE_P(
    Settings, TrpoUpdate,
    ::testing::Values(Case{"Gaussian", "Pendulum-v1",
                           "n_steps: 64\nbatch_size: 32\nn_critic_updates: 3\ntarget_kl: 0.02\n"
                           "policy: {net_arch: [16, 16]}\n",
                           Search::kFullStep},
                      Case{"Categorical", "CartPole-v1",
                           "n_steps: 64\nbatch_size: 48\nn_critic_updates: 2\ntarget_kl: 0.01\n"
                           "cg_max_steps: 8\ncg_damping: 0.05\npolicy: {net_arch: [16]}\n",
                           Search::kFullStep},
                      Case{"GaussianBacktracks", "Pendulum-v1",
                           "n_steps: 64\nbatch_size: 32\nn_critic_updates: 3\ntarget_kl: 0.1\n"
                           "cg_damping: 0.0001\npolicy: {net_arch: [16, 16]}\n",
                           Search::kBacktracks},
                      Case{"CategoricalRejects", "CartPole-v1",
                           "n_steps: 64\nbatch_size: 48\nn_critic_updates: 2\ntarget_kl: 0.5\n"
                           "cg_damping: 0.0001\npolicy: {net_arch: [16]}\n",
                           Search::kRejects}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

}  // namespace
}  // namespace tendril::rl
