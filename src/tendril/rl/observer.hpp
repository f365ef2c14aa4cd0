#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tendril/envs/vector/vec_step.hpp"

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
  // Mean curriculum level of the last 100 episodes (unset if the env has no curriculum).
  std::optional<double> curriculum_level;
  TrainStats train;
  // Wall time of this iteration: stepping the environments, policy inference, the updates.
  double env_seconds = 0.0, inference_seconds = 0.0, update_seconds = 0.0;
};

// One vector-env step of collection, as an observer sees it.
struct StepEvent {
  const envs::BatchMatrix& observations;  // what the actions were chosen from
  const envs::BatchMatrix& actions;       // what the environments received (env units)
  const envs::VecStep& step;              // what came back
  int64_t timesteps;                      // environment steps so far, this step included
};

// Something that watches training (SB3's callbacks): both algorithm families report every
// vector-env step and every iteration to their observers. Logging, evaluation, checkpoints,
// the progress line, dashboards, curricula, co-trained critics and data collection are
// observers; none needs to know the algorithm's type.
class Observer {
 public:
  virtual ~Observer() = default;
  virtual void on_step(const StepEvent& /*event*/) {}
  // After each iteration; returning false stops `learn` after this iteration (every observer
  // still sees it).
  virtual bool on_iteration(const Progress& /*progress*/) { return true; }
};

using Observers = std::vector<Observer*>;

// An observer made of a function of each iteration's progress.
class IterationCallback : public Observer {
 public:
  explicit IterationCallback(std::function<bool(const Progress&)> callback)
      : callback_(std::move(callback)) {}
  bool on_iteration(const Progress& progress) override { return callback_(progress); }

 private:
  std::function<bool(const Progress&)> callback_;
};

}  // namespace tendril::rl
