#pragma once

// One policy of every exportable kind and shape, with random weights (large enough that the
// squashes saturate for some observations and the clips act) and, for most, an observation
// normalization whose clip acts too: what the export tests check against Policy::act.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/rl/actor_critic_policy.hpp"
#include "tendril/rl/dqn/q_greedy_policy.hpp"
#include "tendril/rl/sac/squashed_gaussian_policy.hpp"
#include "tendril/rl/td3/deterministic_policy.hpp"

namespace tendril::testing {

struct SamplePolicy {
  std::string name;  // a C identifier
  std::unique_ptr<rl::Policy> policy;
};

// Weights uniform in ±gain/√fan_in-ish: every entry in ±gain/√inputs, so pre-activations are
// of order `gain` (large gains saturate the tanh squash for some inputs).
inline void randomize(Eigen::VectorXf& parameters, int64_t inputs, double gain, Rng& rng) {
  const double bound = gain / std::sqrt(static_cast<double>(inputs));
  for (Eigen::Index i = 0; i < parameters.size(); ++i) {
    parameters[i] = static_cast<float>(rng.uniform(-bound, bound));
  }
}

// Statistics of a stream with per-component offsets and spreads; clip 3 so that far
// observations are clipped.
inline rl::ObservationNormalization sample_normalization(int size, Rng& rng) {
  envs::RunningMeanStd statistics(size);
  Eigen::MatrixXd samples(64, size);
  for (int j = 0; j < size; ++j) {
    const double offset = rng.uniform(-2.0, 2.0), spread = rng.uniform(0.2, 3.0);
    for (int i = 0; i < samples.rows(); ++i) samples(i, j) = offset + spread * rng.normal();
  }
  statistics.update_batch(samples);
  return {statistics, 3.0, 1e-8};
}

inline std::vector<SamplePolicy> sample_policies(uint64_t seed = 7) {
  Rng rng(seed);
  const Space observations = Space::box(6, -10.0f, 10.0f);
  Eigen::VectorXf low(3), high(3);
  low << -2.0f, 0.0f, -0.5f;
  high << 2.0f, 1.0f, 1.5f;
  const Space box = Space::box(low, high);
  std::vector<SamplePolicy> policies;
  const auto add = [&](std::string name, std::unique_ptr<rl::Policy> policy, bool normalized) {
    if (normalized) {
      policy->set_observation_normalization(
          sample_normalization(policy->observation_space().size(), rng));
    }
    policies.push_back({std::move(name), std::move(policy)});
  };

  nn::ActorCriticSpec ppo;  // SB3's MlpPolicy: 64×64 tanh trunks
  auto gaussian = std::make_unique<rl::ActorCriticPolicy>(observations, box, ppo);
  randomize(gaussian->parameters(), 6, 2.0, rng);
  add("ppo_gaussian", std::move(gaussian), true);

  nn::ActorCriticSpec shared;  // relu, one shared trunk, a softsign mean (seed 002's actor)
  shared.policy_layers = {32, 16};
  shared.shared_trunk = true;
  shared.activation = nn::Activation::kRelu;
  shared.policy_output_activation = nn::Activation::kSoftsign;
  auto softsign = std::make_unique<rl::ActorCriticPolicy>(observations, box, shared);
  randomize(softsign->parameters(), 6, 2.0, rng);
  add("trpo_softsign", std::move(softsign), false);

  nn::ActorCriticSpec linear;  // no trunk: the head reads the observation
  linear.policy_layers = {};
  linear.value_layers = {8};
  auto direct = std::make_unique<rl::ActorCriticPolicy>(observations, box, linear);
  randomize(direct->parameters(), 6, 1.0, rng);
  add("ppo_linear", std::move(direct), true);

  auto categorical = std::make_unique<rl::ActorCriticPolicy>(observations, Space::discrete(4),
                                                             nn::ActorCriticSpec{});
  randomize(categorical->parameters(), 6, 2.0, rng);
  add("ppo_categorical", std::move(categorical), true);

  auto sac = std::make_unique<rl::SquashedGaussianPolicy>(
      observations, box, std::vector<int64_t>{32, 32}, nn::Activation::kRelu, false);
  randomize(sac->parameters(), 6, 2.0, rng);
  add("sac", std::move(sac), true);

  auto sde = std::make_unique<rl::SquashedGaussianPolicy>(
      observations, box, std::vector<int64_t>{16}, nn::Activation::kTanh, true);
  randomize(sde->parameters(), 6, 3.0, rng);
  add("sac_gsde", std::move(sde), false);

  auto td3 = std::make_unique<rl::DeterministicPolicy>(
      observations, box, std::vector<int64_t>{32, 32}, nn::Activation::kRelu);
  randomize(td3->parameters(), 6, 2.0, rng);
  add("td3", std::move(td3), true);

  auto dqn = std::make_unique<rl::QGreedyPolicy>(
      observations, Space::discrete(5), std::vector<int64_t>{24, 24}, nn::Activation::kRelu);
  randomize(dqn->parameters(), 6, 2.0, rng);
  add("dqn", std::move(dqn), true);

  auto bounded = std::make_unique<rl::QGreedyPolicy>(
      observations, Space::discrete(3), std::vector<int64_t>{16}, nn::Activation::kTanh, 10.0);
  randomize(bounded->parameters(), 6, 2.0, rng);
  add("dqn_bounded", std::move(bounded), false);
  return policies;
}

// Observations spread around and well beyond the normalization's range.
inline Eigen::MatrixXf sample_observations(int count, int size, uint64_t seed) {
  Rng rng(seed);
  Eigen::MatrixXf observations(count, size);
  for (Eigen::Index i = 0; i < observations.size(); ++i) {
    observations.data()[i] = static_cast<float>(4.0 * rng.normal());
  }
  return observations;
}

}  // namespace tendril::testing
