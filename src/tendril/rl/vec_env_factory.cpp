#include "tendril/rl/vec_env_factory.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"
#include "tendril/envs/wrappers/normalize_observation.hpp"
#include "tendril/envs/wrappers/normalize_reward.hpp"

namespace tendril::rl {

std::unique_ptr<envs::VecEnv> make_vec_env(const VecEnvOptions& options) {
  require(options.n_envs >= 1, "n_envs must be at least 1", "rl::make_vec_env");
  auto factory = [&options](int) -> std::unique_ptr<Env> {
    std::unique_ptr<Env> env = envs::make(options.id, options.params);
    env = std::make_unique<envs::EpisodeStatistics>(std::move(env));
    if (options.normalize_observation) {
      env = std::make_unique<envs::NormalizeObservation>(std::move(env));
    }
    if (options.normalize_reward) {
      envs::NormalizeReward::Options reward_options;
      reward_options.gamma = options.reward_gamma;
      env = std::make_unique<envs::NormalizeReward>(std::move(env), reward_options);
    }
    return env;
  };
  return std::make_unique<envs::VecEnv>(options.n_envs, factory, options.num_threads);
}

std::unique_ptr<Env> make_evaluation_env(const VecEnvOptions& options, Env& training_env) {
  std::unique_ptr<Env> env = envs::make(options.id, options.params);
  if (options.normalize_observation) {
    auto normalizer = std::make_unique<envs::NormalizeObservation>(std::move(env));
    const auto* trained = envs::find_wrapper<envs::NormalizeObservation>(training_env);
    require(trained != nullptr, "the training environment does not normalize observations",
            "rl::make_evaluation_env");
    normalizer->set_statistics(trained->statistics());
    normalizer->set_training(false);
    env = std::move(normalizer);
  }
  return env;
}

}  // namespace tendril::rl
