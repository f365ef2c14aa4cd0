#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/core/env.hpp"
#include "tendril/envs/vector/vec_env.hpp"

namespace tendril::rl {

// Named scalars of one update, with Stable-Baselines3's logger names ("train/approx_kl", …).
using TrainStats = std::vector<std::pair<std::string, double>>;

// What `learn` reports after each iteration (on-policy: rollout + update; off-policy: a block
// of `log_interval` steps with their gradient steps).
struct Progress {
  int64_t timesteps = 0;             // environment steps so far, over all envs
  int64_t iterations = 0;            // iterations so far
  double episode_return_mean = 0.0;  // over the last 100 finished episodes (0 if none)
  double episode_length_mean = 0.0;
  int64_t episodes = 0;  // finished episodes so far
  // Over the last 100 episodes that reported "is_success" (unset if the env reports none).
  std::optional<double> success_rate;
  TrainStats train;
  // Wall time of this iteration: stepping the environments, policy inference, the updates.
  double env_seconds = 0.0, inference_seconds = 0.0, update_seconds = 0.0;
};

// What the trainer, evaluation and the command line need of any algorithm (PPO, TRPO, SAC,
// TD3, DDPG, DQN). Each algorithm trains on a VecEnv it borrows, which must outlive it.
class Algorithm {
 public:
  // Returning false from the callback stops `learn` after the current iteration.
  using Callback = std::function<bool(const Progress&)>;

  virtual ~Algorithm() = default;

  // Trains until `total_timesteps` environment steps have been taken in all (calls to `learn`
  // continue the count; schedules anneal over `total_timesteps`).
  virtual void learn(int64_t total_timesteps, const Callback& callback) = 0;

  // The policy's actions for a batch (one row per observation, one row per action), the mode
  // when `deterministic`, in the environment's action space.
  virtual envs::BatchMatrix predict(const envs::BatchMatrix& observations, bool deterministic) = 0;
  // The same for one observation.
  Action predict(const Observation& observation, bool deterministic) {
    const envs::BatchMatrix batch = observation.transpose();
    return predict(batch, deterministic).row(0).transpose();
  }

  // Everything needed to resume — weights, optimizer state, RNG states, counters, normalizer
  // statistics — written atomically. `load` restores a checkpoint of the same algorithm and
  // architecture; a missing, corrupt or mismatching file raises Error and changes nothing.
  virtual void save(const std::filesystem::path& file) const = 0;
  virtual void load(const std::filesystem::path& file) = 0;

  // Makes the next step start from a seeded reset of every environment, as it does after
  // `load`. The trainer calls it at each checkpoint so that a run resumed from that checkpoint
  // and the uninterrupted run are the same computation.
  virtual void restart_environments() = 0;

  virtual int64_t num_timesteps() const = 0;
  virtual const std::string& name() const = 0;
};

// Raises Error naming `where` unless `observations` has `size` finite components per row.
void check_observations(const envs::BatchMatrix& observations, int size, const std::string& where);

}  // namespace tendril::rl
