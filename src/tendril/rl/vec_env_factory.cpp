#include "tendril/rl/vec_env_factory.hpp"

#include "tendril/core/error.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/vector/threaded_vec_env.hpp"
#include "tendril/envs/vector/vec_normalize.hpp"
#include "tendril/envs/wrappers/episode_statistics.hpp"
#include "tendril/envs/wrappers/normalize_observation.hpp"
#include "tendril/envs/wrappers/wrapper_registry.hpp"

namespace tendril::rl {

std::unique_ptr<envs::VecEnv> make_vec_env(const VecEnvOptions& options) {
  require(options.n_envs >= 1, "n_envs must be at least 1", "rl::make_vec_env");
  // An env that steps N copies at once (a batched learned model) is built as one, unless
  // per-env wrappers are asked for.
  std::unique_ptr<envs::VecEnv> env;
  // Asking for lockstep rods (Elastica/Tracking3D-v0) means one pool under all the copies, which
  // per-env wrappers would go around: refused rather than quietly ignored.
  const bool lockstep =
      options.params.has("lockstep_rods") && options.params.get<bool>("lockstep_rods");
  require(options.wrappers.empty() || !lockstep,
          "lockstep_rods steps the copies together and cannot sit under per-env wrappers; remove "
          "env.wrappers or lockstep_rods",
          options.id);
  if (options.wrappers.empty()) env = envs::make_vector(options.id, options.params, options.n_envs);
  if (!env) {
    auto factory = [&options](int) -> std::unique_ptr<Env> {
      return std::make_unique<envs::EpisodeStatistics>(make_env(options));
    };
    env = std::make_unique<envs::ThreadedVecEnv>(options.n_envs, factory, options.num_threads);
  }
  if (options.normalize_observation || options.normalize_reward) {
    envs::VecNormalize::Options normalize;
    normalize.normalize_observation = options.normalize_observation;
    normalize.normalize_reward = options.normalize_reward;
    normalize.gamma = options.reward_gamma;
    env = std::make_unique<envs::VecNormalize>(std::move(env), normalize);
  }
  return env;
}

std::unique_ptr<Env> make_env(const VecEnvOptions& options) {
  return envs::apply_wrappers(envs::make(options.id, options.params), options.wrappers);
}

std::unique_ptr<Env> make_evaluation_env(const VecEnvOptions& options,
                                         const envs::VecEnv& training_env) {
  std::unique_ptr<Env> env = make_env(options);
  if (options.normalize_observation) {
    const envs::VecNormalize* trained = training_env.normalizer();
    require(trained != nullptr && trained->options().normalize_observation,
            "the training environment does not normalize observations", "rl::make_evaluation_env");
    auto normalizer = std::make_unique<envs::NormalizeObservation>(
        std::move(env),
        envs::NormalizeObservation::Options{.clip = trained->options().clip_observation,
                                            .epsilon = trained->options().epsilon});
    normalizer->set_statistics(trained->observation_statistics());
    normalizer->set_training(false);
    env = std::move(normalizer);
  }
  return env;
}

}  // namespace tendril::rl
