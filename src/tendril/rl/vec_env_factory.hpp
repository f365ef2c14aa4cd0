#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tendril/core/config.hpp"
#include "tendril/envs/vector/vec_env.hpp"

namespace tendril::rl {

// What SB3's make_vec_env (+ VecNormalize) builds for training: `n_envs` copies of a registered
// environment, each wrapped as
//   registry env (with its time limit) → the listed wrappers → EpisodeStatistics,
// in a VecEnv — the registry's batched one for ids that have it (EnvSpec::vector_factory) and no
// wrappers are listed, else a ThreadedVecEnv — that, when either normalization is on, carries one
// VecNormalize shared by all envs (statistics of the whole batch, SB3's semantics), so episode
// returns are reported raw while the learner sees normalized values.
struct VecEnvOptions {
  std::string id;
  Config params;
  // Entries of the experiment's env.wrappers (envs/wrappers/wrapper_registry.hpp), innermost
  // first; every environment the run's policy acts on carries them.
  std::vector<Config> wrappers;
  int n_envs = 1;
  int num_threads = 1;
  bool normalize_observation = false;
  bool normalize_reward = false;
  double reward_gamma = 0.99;  // discount of the return whose std scales rewards
};

std::unique_ptr<envs::VecEnv> make_vec_env(const VecEnvOptions& options);

// One environment as the policy sees it, without statistics or normalization: the registry env
// (with its time limit) in the listed wrappers.
std::unique_ptr<Env> make_env(const VecEnvOptions& options);

// One environment for evaluation (make_env), with raw rewards and, when observations are
// normalized, `training_env`'s shared observation statistics frozen in a NormalizeObservation
// wrapper (SB3's evaluation of a VecNormalize'd model). Episode returns are in the environment's
// own units. Raises Error if observations are to be normalized but `training_env` does not.
std::unique_ptr<Env> make_evaluation_env(const VecEnvOptions& options,
                                         const envs::VecEnv& training_env);

}  // namespace tendril::rl
